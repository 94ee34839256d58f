#!/usr/bin/env bash
# Leave one world out on every test world: prepares the worlds that are not
# prepared yet (scripts/prepare-cars.sh: TORCS and Trigger Rally;
# scripts/prepare-warzone.sh: Warzone 2100's vehicles, its structures as
# clutter; scripts/prepare-sweethome3d.sh: Sweet Home 3D's vehicles), then
# runs `spinhash-experiment worlds` on them and the procedural fleet, on
# every core. Extra arguments go to the experiment (--scans-per-world N,
# --conditions ..., build flags).
#
#   scripts/worlds.sh [OUT_DIR [ARGS...]]
#       OUT_DIR defaults to out/worlds (summary.md, per_scan.csv, the databases);
#       the prepared worlds go to $WORLDS_DATA (default out/): cars, warzone, sweethome3d
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/worlds}
shift $(($# > 0 ? 1 : 0))
experiment=${SPINHASH_EXPERIMENT:-$root/build/experiments/spinhash-experiment}
data=${WORLDS_DATA:-$root/out}
[[ -x "$experiment" ]] || { echo "worlds: no spinhash-experiment binary at $experiment (build first)" >&2; exit 1; }
for world in cars warzone sweethome3d; do
  [[ -f "$data/$world/meshes/catalog.csv" ]] || "$root/scripts/prepare-$world.sh" "$data/$world" "$experiment"
done
"$experiment" worlds --out "$out" --threads "$(nproc)" --catalog "$data/cars/meshes" \
  --catalog "$data/warzone/meshes" --catalog "$data/sweethome3d/meshes" "$@"
