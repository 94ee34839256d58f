#!/usr/bin/env bash
# Flight cost (docs/budgets.md "Instructions per stage"): BRAN's
# instructions per query by stage (features, LSH search, verification, the
# rest) at 17, 56 and 1 000 procedural models, median and worst of the
# instruction benchmark's queries at 0.05 and 0.10 m, against the
# `stage.*` budgets. Callgrind on the host Release build in ./build;
# SPINHASH_STAGE_SIZES narrows the sizes (the 1 000-model fleet takes the
# longest to build).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
host_build=${SPINHASH_HOST_BUILD:-build}
bin=$host_build/host-tools/spinhash
[[ -x "$bin" ]] || { echo "stage-budget: $bin missing (host build first)"; exit 1; }
scripts/instructions-per-stage.sh --spinhash "$bin" --out "$host_build/stage-budget" \
  --sizes "${SPINHASH_STAGE_SIZES:-17,56,1000}" --jobs "$(nproc 2>/dev/null || echo 2)" --check
