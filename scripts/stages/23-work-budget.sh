#!/usr/bin/env bash
# Bounded time (onboard rule 5, docs/onboard-rules.md): worst-case inputs must stop on the work
# budget, say so (budget_exhausted), and stay under the instruction budgets of
# docs/budgets.md. Instructions are counted by callgrind inside
# Recognizer::run only (deterministic for a given binary; recognize's overloads
# tail-call it, so a toggle on them counted 12 instructions); uses the
# host Release build in ./build (scripts/test.sh builds it).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
source scripts/budgets.sh
host_build=${SPINHASH_HOST_BUILD:-build}  # scripts/test.sh builds ./build (Release)
runner=$host_build/tests/worst_case_runner
work=$host_build/worst-case
[[ -x "$runner" ]] || { echo "work-budget: $runner missing (host build first)"; exit 1; }
mkdir -p "$work"
"$runner" prepare "$work" >/dev/null

# Prints the instructions executed inside Recognizer::run by "$@".
count_instructions() {
  local log=$work/callgrind.log
  valgrind --tool=callgrind --callgrind-out-file=/dev/null --collect-atstart=no \
    --toggle-collect='spinhash::Recognizer::run*' "$@" >"$work/stdout.log" 2>"$log" \
    || { cat "$work/stdout.log" "$log"; return 1; }
  grep -E 'budget_exhausted' "$work/stdout.log" | sed 's/^/work-budget:   /' >&2
  awk '/Collected :/ { print $NF }' "$log"
}

status=0
check() {
  local key=$1 measured=$2 limit
  limit=$(budget "$key")
  local verdict=ok
  (( measured <= limit )) || { verdict="OVER BUDGET"; status=1; }
  printf 'work-budget: %-24s %14s instructions (budget %s) %s\n' "$key" "$measured" "$limit" "$verdict"
}

for case in max_points symmetric huge_buckets; do
  check "instr.$case" "$(count_instructions "$runner" run "$work" "$case")"
done
check "instr.golden_all" "$(count_instructions "$runner" golden tests/golden)"
exit $status
