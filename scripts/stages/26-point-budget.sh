#!/usr/bin/env bash
# Work per point of the scene stream (docs/budgets.md "Work per
# point"): instructions per input point by stage on the stream runner's
# 100 m strip (callgrind, x86-64 host Release build in ./build), against the
# `point.*` budgets. Checked like the other instruction budgets: a changed
# stage that costs more per point fails here, not in a note.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
source scripts/budgets.sh
host_build=${SPINHASH_HOST_BUILD:-build}
out=$host_build/point-budget
scripts/instructions-per-point.sh --host-build "$host_build" --out "$out" >"$out.log" 2>&1 \
  || { cat "$out.log"; echo "point-budget: the measurement failed"; exit 1; }
grep -E '^host:' "$out.log" | sed 's/^/point-budget: /'
status=0
while IFS=, read -r stage points instructions _; do
  [[ "$stage" =~ ^(total|terrain|segmentation|recognition)$ ]] || continue
  measured=$(( instructions / points ))
  limit=$(budget "point.$stage")
  verdict=ok
  (( measured <= limit )) || { verdict="OVER BUDGET"; status=1; }
  printf 'point-budget: %-20s %6s instructions per point (budget %s) %s\n' "point.$stage" "$measured" "$limit" \
    "$verdict"
done < "$out/instructions-per-point.csv"
exit $status
