#!/usr/bin/env bash
# The mutation run of the paper-A engine in pieces, recorded in the repository: it runs the
# shards of scripts/mutants.sh that evidence/mutants/ holds no outcome for yet, one after
# another, and files each finished shard's outcome there, to be committed. The whole run
# takes about 5 hours of both cores, longer than a working session; what a session
# finishes is kept, and the next session goes on from there.
#
#   scripts/mutants-evidence.sh [K ...]   # the given shards (default: every one not done)
#   scripts/mutants-evidence.sh --score   # the score over the shards done so far
#
# evidence/mutants/list.txt is the list of mutants the run was started on (cargo mutants
# --list). Outcomes of shards add up only over one list, so the script refuses to run when
# the engine's mutated code no longer gives that list (a change to the engine starts the
# run again: delete evidence/mutants/). New tests do not change it. Each shard runs at the
# commit checked out (HEAD) in a separate worktree (target/mutants-work), with
# cargo-mutants' --in-place, so the build is kept from shard to shard; its outcome records
# that commit.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
ev=evidence/mutants
shards=40
files=(src/quad.rs src/contain.rs src/proximity.rs src/detect/*.rs src/well_formed.rs src/predicates.rs)
file_args=()
for f in "${files[@]}"; do file_args+=(--file "$f"); done

score() {
  local done=0 caught=0 missed=0 unviable=0 timeout=0
  for d in "$ev"/shard-*/; do
    [ -f "$d/commit" ] || continue
    done=$((done + 1))
    caught=$((caught + $(wc -l < "$d/caught.txt")))
    missed=$((missed + $(wc -l < "$d/missed.txt")))
    unviable=$((unviable + $(wc -l < "$d/unviable.txt")))
    timeout=$((timeout + $(wc -l < "$d/timeout.txt")))
  done
  echo "shards done: $done of $shards ($(wc -l < "$ev/list.txt") mutants in all)"
  echo "caught $caught, missed $missed, timeout $timeout, unviable $unviable"
  # Each missed mutant is sorted in $ev/sorted.tsv (the arguments: docs/mutation.md):
  # killed by a later test, equivalent, equivalent under the contract (speed only), or a
  # survivor (rounding slack, less decisive). Timeouts count as caught (cargo-mutants'
  # own rule: the mutant hangs the tests).
  local missed_list=()
  for d in "$ev"/shard-*/; do
    [ -f "$d/commit" ] && missed_list+=("$d/missed.txt")
  done
  [ ${#missed_list[@]} -gt 0 ] || missed_list=(/dev/null)
  awk -F'\t' -v caught=$((caught + timeout)) '
    FNR == NR { if ($0 !~ /^#/) class[$1] = $2; next }
    { c = ($0 in class) ? class[$0] : "unsorted"; n[c]++; if (c == "unsorted") u = u "\n  " $0 }
    END {
      killed = caught + n["killed"]
      survivors = n["slack"] + n["decisive"] + n["open"] + n["unsorted"]
      printf "missed: %d killed since by a test, %d equivalent, %d equivalent under the contract (speed only), %d rounding slack, %d less decisive, %d open (may be unsound; no test yet), %d not yet sorted%s\n", n["killed"], n["equivalent"], n["contract"], n["slack"], n["decisive"], n["open"], n["unsorted"], u
      if (killed + survivors > 0)
        printf "score: %d of %d non-equivalent mutants killed (%.1f %%); %.1f %% with the speed-only ones counted as survivors\n", killed, killed + survivors, 100 * killed / (killed + survivors), 100 * killed / (killed + survivors + n["contract"])
    }' "$ev/sorted.tsv" "${missed_list[@]}"
}

if [ "${1:-}" = "--score" ]; then
  score
  exit 0
fi

if ! cargo mutants --version >/dev/null 2>&1; then
  cargo install cargo-mutants --locked
fi
work="$root/target/mutants-work"
if [ ! -d "$work" ]; then
  git worktree add --detach "$work" HEAD >/dev/null
else
  # a session cut off mid-shard leaves a mutant in place: undo it first; and the tests
  # of mutants leave proptest's seeds of their failures (untracked), which a checkout of
  # a commit that tracks the same file refuses to overwrite
  git -C "$work" reset -q --hard
  git -C "$work" clean -fdq
  git -C "$work" checkout -q --detach "$(git rev-parse HEAD)"
fi
commit=$(git -C "$work" rev-parse HEAD)
mkdir -p "$ev"
list="$root/target/mutants-list.txt"
(cd "$work" && cargo mutants --list --package polyguard "${file_args[@]}") > "$list"
if [ -f "$ev/list.txt" ]; then
  shards=$(cat "$ev/shards")
  if ! cmp -s "$list" "$ev/list.txt"; then
    # The engine changed. cargo-mutants cuts the list into contiguous slices of
    # ceil(N/shards) mutants, so a finished slice keeps its meaning when the slice size is
    # the same and the list is unchanged, line for line, up to the slice's last mutant
    # (the change lies after it). Then the new list replaces the old one; otherwise the
    # outcomes would not add up, and the run must start again.
    old_n=$(wc -l < "$ev/list.txt")
    new_n=$(wc -l < "$list")
    old_size=$(((old_n + shards - 1) / shards))
    new_size=$(((new_n + shards - 1) / shards))
    same=$({ cmp "$ev/list.txt" "$list" 2>/dev/null || true; } | sed -n 's/.* line \([0-9]*\).*/\1/p')
    same=$((${same:-$((old_n < new_n ? old_n : new_n)) + 1} - 1))   # identical leading lines
    stale=()
    for d in "$ev"/shard-*/; do
      [ -f "$d/commit" ] || continue
      k=$(basename "$d"); k=${k#shard-}
      if [ "$old_size" -ne "$new_size" ] || [ $(((k + 1) * new_size)) -gt "$same" ]; then
        stale+=("$k")
      fi
    done
    if [ ${#stale[@]} -gt 0 ]; then
      diff "$ev/list.txt" "$list" | head -20 >&2
      echo "mutants-evidence: the engine's mutants changed within finished slices" \
        "(${stale[*]}; slice size $old_size, now $new_size): outcomes of different lists do" \
        "not add up (delete those slices, or $ev to start again)" >&2
      exit 2
    fi
    echo "mutants-evidence: the list changed after its first $same mutants; the finished" \
      "slices lie before that and are kept; $ev/list.txt is now the new list ($new_n mutants)" >&2
    cp "$list" "$ev/list.txt"
  fi
else
  cp "$list" "$ev/list.txt"
  echo "$shards" > "$ev/shards"
fi
shards=$(cat "$ev/shards")

todo=("$@")
if [ ${#todo[@]} -eq 0 ]; then
  for ((k = 0; k < shards; k++)); do todo+=("$k"); done
fi
for k in "${todo[@]}"; do
  dir="$ev/shard-$k"
  [ -f "$dir/commit" ] && continue
  out="$root/target/mutants-out/shard-$k"
  rm -rf "$out" && mkdir -p "$root/target/mutants-out"
  set +e
  MUTANTS_OUT="$out" "$work/scripts/mutants.sh" --shard "$k/$shards" --in-place \
    > "$root/target/mutants-out/shard-$k.log" 2>&1
  code=$?
  set -e
  # cargo-mutants: 0 all caught, 2 some missed, 3 some timed out; anything else (a
  # failing baseline, a usage error) is no outcome
  if [ "$code" -ne 0 ] && [ "$code" -ne 2 ] && [ "$code" -ne 3 ]; then
    echo "mutants-evidence: shard $k/$shards did not run (exit $code): target/mutants-out/shard-$k.log" >&2
    exit "$code"
  fi
  mkdir -p "$dir"
  for f in caught missed unviable timeout; do
    sort "$out/mutants.out/$f.txt" > "$dir/$f.txt"
  done
  echo "$commit" > "$dir/commit"   # last: a shard with a commit file is complete
  echo "shard $k/$shards: $(wc -l < "$dir/caught.txt") caught, $(wc -l < "$dir/missed.txt") missed," \
    "$(wc -l < "$dir/timeout.txt") timeout, $(wc -l < "$dir/unviable.txt") unviable (at ${commit:0:7})"
done
score
