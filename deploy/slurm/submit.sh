#!/usr/bin/env bash
# Submits an N-shard assure campaign and its merge, which runs when every shard has ended.
#   deploy/slurm/submit.sh N [CASES] [SEED]
set -euo pipefail
n="${1:?usage: submit.sh N [CASES] [SEED]}"
export CASES="${2:-100000000}" SEED="${3:-1}" RESULTS="${RESULTS:-$PWD/assure-results}"
here="$(cd "$(dirname "$0")" && pwd)"
array=$(sbatch --parsable --export=ALL --array=0-$((n - 1)) "$here/assure-array.sbatch")
merge=$(sbatch --parsable --export=ALL --dependency=afterany:"$array" "$here/merge.sbatch")
echo "shards: job $array (0..$((n - 1))), merge: job $merge, results in $RESULTS"
