#!/usr/bin/env bash
# Short cargo-fuzz runs of every target, called from .ci/run; exits non-zero when a target
# finds a crash (a missed detection, a far false alarm, a panic). Longer campaigns: README.md.
#   fuzz/ci.sh [SECONDS_PER_TARGET]   (default 20)
set -euo pipefail
cd "$(dirname "$0")"
secs="${1:-20}"
targets=(diff_same_2d diff_diff_2d diff_3d parse_jsonl parse_scenario api_arbitrary paper_b intervals moving_formats)

# cargo-fuzz needs a nightly compiler (-Zsanitizer). Use the nightly toolchain when the
# machine has one; otherwise let the stable compiler accept the nightly flags.
if rustup run nightly rustc --version >/dev/null 2>&1; then
  cargo_fuzz=(cargo +nightly fuzz)
else
  echo "fuzz/ci.sh: no nightly toolchain; using stable with RUSTC_BOOTSTRAP=1" >&2
  export RUSTC_BOOTSTRAP=1
  cargo_fuzz=(cargo fuzz)
fi
if ! cargo fuzz --version >/dev/null 2>&1; then
  cargo install cargo-fuzz --locked
fi

"${cargo_fuzz[@]}" build
# Seeds: parse_jsonl starts from every case file the project has; the differential
# targets from each regression case, one line a file (an input starting with '{' is read
# as a case line).
mkdir -p corpus/parse_jsonl corpus/parse_scenario corpus/moving_formats
cp ../examples/*.jsonl ../tests/regressions/*.jsonl corpus/parse_jsonl/ 2>/dev/null || true
cp ../examples/*.geojson ../tests/scenarios/*.geojson corpus/parse_scenario/ 2>/dev/null || true
# moving_formats from the real traffic, MovingPandas and FIR excerpts the tests read
cp ../crates/earth/tests/data/moving/* corpus/moving_formats/ 2>/dev/null || true
for t in diff_same_2d diff_diff_2d diff_3d; do
  mkdir -p "corpus/$t"
  cat ../tests/regressions/*.jsonl | awk -v dir="corpus/$t" 'NF { print > (dir "/regression-" NR ".json") }'
done
for t in "${targets[@]}"; do
  echo "=== fuzz $t (${secs}s)"
  "${cargo_fuzz[@]}" run "$t" -- -max_total_time="$secs" -print_final_stats=1 2>&1 |
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|Done )|panicked|SUMMARY|Test unit written' || true
  # grep hides libFuzzer's chatter, not its verdict: the pipeline's status is cargo fuzz's.
  if [ "${PIPESTATUS[0]}" -ne 0 ]; then
    echo "fuzz target $t failed; the input is in fuzz/artifacts/$t/" >&2
    exit 1
  fi
done
