#!/usr/bin/env bash
# Mutation testing of the paper-A engine.
#
#   scripts/mutants.sh [--shard k/N] [any other cargo-mutants option]
#
# Mutates the engine's paper-A modules (quad, contain, proximity, detect, well_formed,
# predicates) and runs, for each mutant, a test command sized for a 2-core machine: the
# engine's unit tests, the function-by-function comparison with the oracle, the
# certified predicates' adversarial tests, the regression corpus, the differential
# proptest over the scale-space generators and the slice functions' long-path cases
# (POLYGUARD_PROPTEST_CASES=256). It builds with the `mutants` profile (Cargo.toml): the
# engine and its dependents at debug speed, rebuilt in about 5 s a mutant, the oracle and
# every dependency optimised, so the tests take about 9 s instead of 30–150 s. The outcome
# goes to $MUTANTS_OUT/mutants.out/ (default target/mutants: caught.txt, missed.txt,
# timeout.txt, unviable.txt, outcomes.json).
#
# The whole set is about 1,300 mutants at about 15 s each on 2 cores: split it with
# --shard k/N (cargo-mutants' own sharding; the shards are disjoint and together cover
# every mutant), on one machine or as an array job (deploy/).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! cargo mutants --version >/dev/null 2>&1; then
  cargo install cargo-mutants --locked
fi
export POLYGUARD_PROPTEST_CASES="${POLYGUARD_PROPTEST_CASES:-256}"
files=(src/quad.rs src/contain.rs src/proximity.rs src/detect/*.rs src/well_formed.rs src/predicates.rs)
args=()
for f in "${files[@]}"; do args+=(--file "$f"); done
exec cargo mutants --package polyguard --test-package polyguard "${args[@]}" \
  --profile mutants --output "${MUTANTS_OUT:-target/mutants}" --timeout 300 --build-timeout 900 "$@" -- \
  --lib --test paper_a_functions_vs_oracle --test paper_a_certified \
  --test paper_a_regressions --test paper_a_differential --test paper_a_low_level
