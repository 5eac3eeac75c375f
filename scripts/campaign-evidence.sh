#!/usr/bin/env bash
# A long assurance campaign (10⁷ or 10⁸ cases) in pieces,
# recorded in the repository. It runs the shards that evidence/campaign-<name>/ holds no
# report for yet, one after another, and files each finished shard there, to be
# committed; the next session goes on from there. When every shard is done, `assure
# merge` makes the campaign's report (exit 1 if any shard found a failure).
#
#   scripts/campaign-evidence.sh NAME [SHARDS CASES SEED [FLAGS]]   # start, or go on with, NAME
#   e.g. scripts/campaign-evidence.sh 1e8-seed1 100 100000000 1
#        scripts/campaign-evidence.sh intervals-1e7-seed12 20 10000000 12 --intervals
# FLAGS (recorded in the plan with the rest) go to every shard's `assure`: `--intervals`
# runs the interval hunt.
#
# The engine judged is the one of the commit recorded when the campaign started
# (evidence/campaign-NAME/commit): the script builds that commit (with the GMP oracle,
# --features rug) in a worktree, so every shard of one campaign judges the same engine
# however far main has moved. A shard keeps its report.json, its log line, and the
# case files of the counterexamples it kept, without their pictures: the merge takes the
# five lowest-indexed per class and draws their pictures again.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
name="${1:?usage: campaign-evidence.sh NAME [SHARDS CASES SEED]}"
ev="$root/evidence/campaign-$name"
if [ ! -f "$ev/commit" ]; then
  [ $# -ge 4 ] || { echo "campaign-evidence: a new campaign needs SHARDS CASES SEED [FLAGS]" >&2; exit 2; }
  mkdir -p "$ev"
  printf '%s %s %s %s\n' "$2" "$3" "$4" "${*:5}" > "$ev/plan"
  git rev-parse HEAD > "$ev/commit"
fi
read -r shards cases seed flags < "$ev/plan"
commit=$(cat "$ev/commit")

work="$root/target/campaign-work"
if [ ! -d "$work" ]; then
  git worktree add --detach "$work" "$commit" >/dev/null
else
  git -C "$work" reset -q --hard
  git -C "$work" checkout -q --detach "$commit"
fi
(cd "$work" && cargo build -q --release -p polyguard-cli --features rug)
bin="$work/target/release/polyguard"

runs="$root/target/campaign-runs/$name"
mkdir -p "$runs"
for ((i = 0; i < shards; i++)); do
  [ -f "$ev/shard-$i/report.json" ] && continue
  tmp="$runs/shard-$i"
  rm -rf "$tmp"
  set +e
  # shellcheck disable=SC2086 # FLAGS are words
  "$bin" assure $flags --cases "$cases" --seed "$seed" --shard "$i/$shards" --quiet --out "$tmp" \
    > "$runs/shard-$i.log" 2>&1
  code=$?
  set -e
  if [ "$code" -gt 1 ]; then
    echo "campaign-evidence: shard $i/$shards failed to run (exit $code, $runs/shard-$i.log)" >&2
    exit "$code"
  fi
  # filed last and whole: a shard folder with a report.json is complete
  rm -rf "$ev/shard-$i.tmp"
  cp -r "$tmp" "$ev/shard-$i.tmp"
  # the pictures stay behind (8 kB each, 10 a shard): the merge draws the ones it keeps
  # again from their case files
  rm -f "$ev/shard-$i.tmp"/counterexamples/*.svg
  # the PASS or FAIL line (the last line of a paper-A run, the first of an interval hunt)
  grep -m 1 -E '^(PASS|FAIL)' "$runs/shard-$i.log" > "$ev/shard-$i.tmp/verdict.txt" ||
    tail -n 1 "$runs/shard-$i.log" > "$ev/shard-$i.tmp/verdict.txt"
  mv "$ev/shard-$i.tmp" "$ev/shard-$i"
  echo "shard $i/$shards: $(cat "$ev/shard-$i/verdict.txt")"
done
"$bin" assure merge "$ev"/shard-*/report.json --out "$ev/merged"
