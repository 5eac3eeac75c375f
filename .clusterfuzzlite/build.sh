#!/usr/bin/env bash
# Builds polyguard's cargo-fuzz targets (fuzz/Cargo.toml, [[bin]] entries) into $OUT, each
# with a seed corpus zip when fuzz/corpus/<target>/ has inputs. Run by ClusterFuzzLite
# inside its image (SRC, OUT, WORK set; the image's nightly toolchain and cargo-fuzz);
# also runs on a plain machine with SRC, OUT and WORK set (CI does, see .ci/run).
set -euo pipefail
: "${OUT:?set OUT to the output directory}"
: "${WORK:=${TMPDIR:-/tmp}/cflite-work}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ -n "${SRC:-}" ] && [ -f "$SRC/polyguard/fuzz/Cargo.toml" ]; then
  repo="$SRC/polyguard"
else
  repo="$(dirname "$here")"
fi
mkdir -p "$OUT" "$WORK"
cd "$repo/fuzz"

# Outside the OSS-Fuzz image: pick nightly as fuzz/ci.sh does.
if command -v rustup >/dev/null 2>&1 && rustup run nightly rustc --version >/dev/null 2>&1; then
  fuzz=(cargo +nightly fuzz)
  rustc_vv=$(rustup run nightly rustc -vV)
else
  fuzz=(cargo fuzz)
  rustc_vv=$(rustc -vV)
fi
triple=$(printf '%s\n' "$rustc_vv" | sed -n 's/^host: //p')
target_dir="${CARGO_TARGET_DIR:-$repo/fuzz/target}"

# Optimised, with debug assertions and overflow checks (an overflow in the engine is a bug
# the fuzzer should report): the flags of a plain `cargo fuzz build`, so fuzz/ci.sh's runs
# reuse these binaries.
"${fuzz[@]}" build -O --debug-assertions
targets=$(sed -n '/^\[\[bin\]\]/,/^$/ s/^name *= *"\(.*\)"/\1/p' Cargo.toml)
for t in $targets; do
  bin="$target_dir/$triple/release/$t"
  if [ ! -x "$bin" ]; then
    echo "build.sh: $bin was not built" >&2
    exit 1
  fi
  cp "$bin" "$OUT/$t"
  if [ -d "corpus/$t" ] && [ -n "$(ls -A "corpus/$t" 2>/dev/null)" ]; then
    rm -f "$OUT/${t}_seed_corpus.zip"
    if command -v zip >/dev/null 2>&1; then
      (cd "corpus/$t" && zip -q -r "$OUT/${t}_seed_corpus.zip" .)
    else
      (cd "corpus/$t" && python3 -m zipfile -c "$OUT/${t}_seed_corpus.zip" .)
    fi
  fi
done
echo "build.sh: $(echo "$targets" | wc -w) fuzz targets in $OUT"
