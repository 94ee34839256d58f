#!/usr/bin/env bash
# An independent test world of real car meshes, never tuned on:
# downloads Debian's torcs-data (333 MB: 17 TORCS car bodies, AC3D) and
# trigger-rally-data (119 MB: 3 distinct Trigger Rally bodies, OBJ) with
# apt-get download (game content under the GPL and other free licences:
# never commit it), unpacks only the cars and converts them to OBJ meshes in
# class folders (spinhash-experiment prepare-cars): 20 cars, 17 sedans and
# 3 "other" in the light group (a buggy, an open-wheel racer, a Baja Bug).
# Not run by CI
# (450 MB of downloads). With the packages installed (scripts/install-deps.sh
# --cars) their files are read in place and nothing is downloaded.
#
#   scripts/prepare-cars.sh [OUT_DIR] [EXPERIMENT_BIN]
#       OUT_DIR defaults to out/cars; meshes land in OUT_DIR/meshes/<class>/, catalog in OUT_DIR/meshes/catalog.csv
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/cars}
spinhash=${2:-$root/build/experiments/spinhash-experiment}
[[ -x "$spinhash" ]] || { echo "prepare-cars: no spinhash-experiment binary at $spinhash (build first)" >&2; exit 1; }
if ! command -v unzip >/dev/null; then
  [[ $(id -u) -eq 0 ]] || { echo "prepare-cars: unzip missing (apt-get install unzip)" >&2; exit 1; }
  apt-get install -y -q unzip >/dev/null
fi
work=$out/download
mkdir -p "$work"
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
# Where the package's files are: / when it is installed, else a folder
# under $work holding the files of a downloaded .deb that match the pattern.
unpack() {
  local pkg=$1 dir=$work/$2 pattern=$3
  if installed "$pkg"; then
    echo /
    return
  fi
  ls "$work/${pkg}"_*.deb >/dev/null 2>&1 || (cd "$work" && apt-get download "$pkg" >&2)
  rm -rf "$dir" && mkdir -p "$dir"
  dpkg-deb --fsys-tarfile "$(ls "$work/${pkg}"_*.deb | sed -n 1p)" | tar -x -C "$dir" --wildcards "$pattern"
  echo "$dir"
}
torcs=$(unpack torcs-data torcs './usr/share/games/torcs/cars/*')
trigger=$(unpack trigger-rally-data trigger './usr/share/games/trigger-rally/data.zip')
rm -rf "$work/trigger-vehicles"
unzip -q "$trigger/usr/share/games/trigger-rally/data.zip" 'vehicles/*' -d "$work/trigger-vehicles"
rm -rf "$out/meshes"
"$spinhash" prepare-cars --torcs "$torcs/usr/share/games/torcs/cars" --trigger "$work/trigger-vehicles/vehicles" \
  -o "$out/meshes"
echo "prepare-cars: meshes in $out/meshes (catalog.csv lists them)"
