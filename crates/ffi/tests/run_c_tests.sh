#!/usr/bin/env bash
# Builds crates/ffi/tests/c/test_polyguard.c with cc against libpolyguard_ffi.a and
# against libpolyguard_ffi.so (-Wall -Wextra -Werror -std=c99 -pedantic), runs both (the
# examples also compared with `polyguard detect --time examples/cases.jsonl`), compiles
# and runs every C example of docs/ffi.md, and compiles the header as C++. With PG_SANITIZE=1, once more under
# -fsanitize=address,undefined, and under valgrind when it is installed.
#
# Environment: CC, CXX (default cc, c++); CARGO_TARGET_DIR; PG_LIB_DIR (where the
# libraries are; when set, nothing is built and the CLI comparison runs only if
# PG_CLI names the polyguard binary).
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
cd "$root"
cc=${CC:-cc}
cxx=${CXX:-c++}
target=${CARGO_TARGET_DIR:-$root/target}
if [ -z "${PG_LIB_DIR:-}" ]; then
  cargo build -q -p polyguard-ffi -p polyguard-cli
  lib="$target/debug"
  cli="$lib/polyguard"
else
  lib=$PG_LIB_DIR
  cli=${PG_CLI:-}
fi
out="$target/ffi-c"
mkdir -p "$out"
inc=crates/ffi/include
src=crates/ffi/tests/c/test_polyguard.c
flags=(-Wall -Wextra -Werror -std=c99 -pedantic -I"$inc")
# what the Rust standard library needs from the system when linked statically (Linux)
static_libs=(-lpthread -ldl -lm)

args=()
if [ -n "$cli" ]; then
  "$cli" detect --time examples/cases.jsonl > "$out/cli.jsonl"
  # pg_encounters' lines against the CLI's on the same files and options (the C test's
  # test_encounters)
  "$cli" encounters crates/earth/tests/data/moving/quickstart-3.csv \
    crates/earth/tests/data/moving/cells-2.mf.json --sep 5 --sep-v 1000 --quiet \
    > "$out/cli-encounters.jsonl"
  args=(--cli "$out/cli.jsonl" --encounters-cli "$out/cli-encounters.jsonl")
fi

echo "== C, static library"
"$cc" "${flags[@]}" "$src" "$lib/libpolyguard_ffi.a" "${static_libs[@]}" -o "$out/test_static"
"$out/test_static" "${args[@]}"

echo "== C, shared library"
"$cc" "${flags[@]}" "$src" -L"$lib" -lpolyguard_ffi -lm -o "$out/test_shared"
# ldd's output captured first: `ldd | grep -q` fails under pipefail when grep's early
# exit kills ldd with SIGPIPE
linked=$(LD_LIBRARY_PATH="$lib" ldd "$out/test_shared")
if [[ $linked != *libpolyguard_ffi.so* ]]; then
  echo "test_shared is not linked against libpolyguard_ffi.so" >&2
  exit 1
fi
LD_LIBRARY_PATH="$lib" "$out/test_shared" "${args[@]}"

echo "== C, the examples of docs/ffi.md (each compiled and run)"
rm -f "$out"/doc-example-*
awk -v dir="$out" '/^```c$/ {n++; on=1; next} /^```$/ {on=0; next} on {print > (dir "/doc-example-" n ".c")}' docs/ffi.md
examples=0
for example in "$out"/doc-example-*.c; do
  [ -e "$example" ] || continue
  "$cc" "${flags[@]}" "$example" "$lib/libpolyguard_ffi.a" "${static_libs[@]}" -o "${example%.c}"
  "${example%.c}"
  examples=$((examples + 1))
done
if [ "$examples" -eq 0 ]; then
  echo "docs/ffi.md has no C example to check" >&2
  exit 1
fi

echo "== C++, the header"
"$cxx" -fsyntax-only -x c++ -std=c++11 -Wall -Wextra -Werror -pedantic "$inc/polyguard.h"

if [ "${PG_SANITIZE:-}" = 1 ]; then
  echo "== C, static library, -fsanitize=address,undefined"
  "$cc" "${flags[@]}" -g -fsanitize=address,undefined -fno-sanitize-recover=all "$src" \
    "$lib/libpolyguard_ffi.a" "${static_libs[@]}" -o "$out/test_asan"
  "$out/test_asan" "${args[@]}"
  if command -v valgrind >/dev/null 2>&1; then
    echo "== C, static library, valgrind"
    # "possibly lost": the thread-local storage of the batch's worker threads (rayon's
    # global pool), which live until the process exits; definite leaks fail the run.
    valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite \
      --show-possibly-lost=no \
      "$out/test_static" "${args[@]}"
  fi
fi
echo "C interface: all checks passed"
