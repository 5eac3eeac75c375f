#!/usr/bin/env bash
# A long campaign on one machine, one shard after another, resumable: a shard whose
# report.json exists is not run again, so the script can be stopped and started again
# (another day, another session) until every shard is done; then it merges them.
#   deploy/resumable-campaign.sh SHARDS CASES SEED OUTDIR [extra assure options]
# (POLYGUARD=path/to/polyguard, best built with --features rug). While shards are
# missing, `polyguard assure merge OUTDIR/shard-*/report.json --partial` shows the
# progress so far.
set -euo pipefail
n="${1:?usage: resumable-campaign.sh SHARDS CASES SEED OUTDIR [options]}"
cases="${2:?}" seed="${3:?}" out="${4:?}"
shift 4
POLYGUARD="${POLYGUARD:-target/release/polyguard}"
mkdir -p "$out"
for ((i = 0; i < n; i++)); do
  dir="$out/shard-$i"
  [ -f "$dir/report.json" ] && continue
  rm -rf "$dir.tmp"
  set +e
  "$POLYGUARD" assure --cases "$cases" --seed "$seed" --shard "$i/$n" --quiet \
    --out "$dir.tmp" "$@" > "$out/shard-$i.log" 2>&1
  code=$?
  set -e
  if [ "$code" -gt 1 ]; then
    echo "resumable-campaign: shard $i/$n failed to run (exit $code, $out/shard-$i.log)" >&2
    exit "$code"
  fi
  mv "$dir.tmp" "$dir"   # only a finished shard gets its final name
  echo "shard $i/$n: $(tail -n 1 "$out/shard-$i.log")"
done
exec "$POLYGUARD" assure merge "$out"/shard-*/report.json --out "$out/merged"
