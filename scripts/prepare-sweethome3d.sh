#!/usr/bin/env bash
# A test world of real-vehicle meshes that nothing in the project is tuned
# on, used only as a left-out world: downloads Debian's sweethome3d-furniture
# (120 MB: Sweet Home 3D's additional furniture libraries, OBJ; CC-BY 3.0
# and CC0, see the package's copyright file) with apt-get download (never
# commit the data), unzips only the vehicles of its .sh3f libraries and
# converts them to OBJ meshes in class folders (spinhash-experiment
# prepare-sweethome3d): 18 vehicles, 9 sedans (hatchbacks, saloons, a
# coupe, a city car), an SUV, 2 vans (an MPV and a panel van), 3 trucks
# (a box lorry and two articulated lorries), 2 buses (a coach and a city
# bus) and a forklift ("other"). Not run by CI. With the package installed
# its files are read in place and nothing is downloaded.
#
#   scripts/prepare-sweethome3d.sh [OUT_DIR] [EXPERIMENT_BIN]
#       OUT_DIR defaults to out/sweethome3d; meshes land in OUT_DIR/meshes/<class>/,
#       catalog in OUT_DIR/meshes/catalog.csv
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/sweethome3d}
spinhash=${2:-$root/build/experiments/spinhash-experiment}
[[ -x "$spinhash" ]] || { echo "prepare-sweethome3d: no spinhash-experiment binary at $spinhash (build first)" >&2; exit 1; }
if ! command -v unzip >/dev/null; then
  [[ $(id -u) -eq 0 ]] || { echo "prepare-sweethome3d: unzip missing (apt-get install unzip)" >&2; exit 1; }
  apt-get install -y -q unzip >/dev/null
fi
pkg=sweethome3d-furniture
libraries=/usr/share/sweethome3d/furniture
work=$out/download
mkdir -p "$work"
if dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
  src=$libraries
else
  ls "$work/${pkg}"_*.deb >/dev/null 2>&1 || (cd "$work" && apt-get download "$pkg")
  rm -rf "$work/x" && mkdir -p "$work/x"
  dpkg-deb --fsys-tarfile "$(ls "$work/${pkg}"_*.deb | sed -n 1p)" |
    tar -x -C "$work/x" --wildcards ".$libraries/*.sh3f"
  src=$work/x$libraries
fi
# Each library's catalog and the folders of its vehicles (the catalog's
# model paths: /<library folder>/<stem>/<stem>.obj).
rm -rf "$work/libraries" && mkdir -p "$work/libraries"
unpack() {
  local library=$1 folder=$2
  shift 2
  local patterns=(PluginFurnitureCatalog.properties)
  for stem in "$@"; do patterns+=("$folder/$stem/*"); done
  unzip -q "$src/$library.sh3f" "${patterns[@]}" -d "$work/libraries/$library"
}
unpack BlendSwap-CC-0 blendswap-cc-0 forkLift peterbilt
unpack BlendSwap-CC-BY blendswap-cc-by fordFocus dafTruck
unpack KatorLegaz katorlegaz concept-sedan-01v1 concept-sedan-02 concept-sedan-02-sport VW-new-beetle
unpack Scopia scopia seat_leon peugeot-308 chevrolet smart-car suv renault-scenic van truck bus cityBus
rm -rf "$out/meshes"
"$spinhash" prepare-sweethome3d --furniture "$work/libraries" -o "$out/meshes"
echo "prepare-sweethome3d: meshes in $out/meshes (catalog.csv lists them)"
