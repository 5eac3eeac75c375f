#!/usr/bin/env bash
# The cluster recipes on one machine: runs deploy/slurm/assure-array.sbatch as the N
# tasks of an array (in parallel, with the environment Slurm would give them), then
# deploy/slurm/merge.sbatch, then the same campaign unsharded, and checks that the merge
# equals the unsharded report exactly on every field but the timings (nanos, entry.nanos,
# wall_seconds) and the list of shards, and that every kept case's files are there.
#   deploy/local-shards.sh N CASES SEED OUTDIR     (POLYGUARD=path/to/polyguard)
set -euo pipefail
n="${1:?usage: local-shards.sh N CASES SEED OUTDIR}"
cases="${2:?}" seed="${3:?}" out="${4:?}"
here="$(cd "$(dirname "$0")" && pwd)"
POLYGUARD="$(realpath "${POLYGUARD:-target/release/polyguard}")"
export POLYGUARD CASES="$cases" SEED="$seed" RESULTS="$out/shards"
rm -rf "$out" && mkdir -p "$out"
pids=()
for ((i = 0; i < n; i++)); do
  SLURM_ARRAY_TASK_ID=$i SLURM_ARRAY_TASK_COUNT=$n SLURM_CPUS_PER_TASK=1 \
    bash "$here/slurm/assure-array.sbatch" > "$out/task-$i.log" 2>&1 &
  pids+=($!)
done
for p in "${pids[@]}"; do
  wait "$p" || { echo "local-shards: a shard task failed (logs in $out)" >&2; exit 2; }
done
set +e
bash "$here/slurm/merge.sbatch" > "$out/merge.log" 2>&1
merge_code=$?
"$POLYGUARD" assure --cases "$cases" --seed "$seed" --quiet --out "$out/whole" > "$out/whole.log" 2>&1
whole_code=$?
set -e
if [ "$merge_code" -ne "$whole_code" ]; then
  echo "local-shards: merge exit $merge_code, unsharded exit $whole_code" >&2
  exit 1
fi
strip='del(.nanos, .wall_seconds, .shards, .entry.nanos)'
if ! diff <(jq -S "$strip" "$RESULTS/merged/report.json") <(jq -S "$strip" "$out/whole/report.json"); then
  echo "local-shards: the merge of $n shards differs from the unsharded run (above)" >&2
  exit 1
fi
for f in $(jq -r '.kept[] | .case_file, .svg_file' "$RESULTS/merged/report.json"); do
  [ -f "$RESULTS/merged/$f" ] || { echo "local-shards: kept file $f is missing" >&2; exit 1; }
done
echo "local-shards: $n shards of $cases cases (seed $seed) merge into exactly the unsharded report (exit $merge_code)"
tail -n 1 "$out/merge.log"
