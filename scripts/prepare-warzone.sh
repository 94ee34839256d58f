#!/usr/bin/env bash
# Real artist-made models for the experiments: reads Debian's
# warzone2100-data (GPL game content: never commit it) in place when it is
# installed, else downloads it with apt-get download; unpacks base.wz and
# converts its vehicles, structures and map features to OBJ meshes
# (spinhash-experiment prepare-warzone).
#
#   scripts/prepare-warzone.sh [OUT_DIR] [EXPERIMENT_BIN]
#       OUT_DIR defaults to out/warzone; meshes land in OUT_DIR/meshes/{vehicles,structures,features}
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/warzone}
spinhash=${2:-$root/build/experiments/spinhash-experiment}
[[ -x "$spinhash" ]] || { echo "prepare-warzone: no spinhash-experiment binary at $spinhash (build first)" >&2; exit 1; }
if ! command -v unzip >/dev/null; then
  [[ $(id -u) -eq 0 ]] || { echo "prepare-warzone: unzip missing (apt-get install unzip)" >&2; exit 1; }
  apt-get install -y -q unzip >/dev/null
fi
work=$out/download
mkdir -p "$work"
# The installed package's base.wz is read in place; else the .deb is
# downloaded and unpacked.
if dpkg-query -W -f='${Status}' warzone2100-data 2>/dev/null | grep -q "install ok installed"; then
  base_wz=$(dpkg -L warzone2100-data | grep '/base\.wz$' | sed -n 1p)
  from="the installed warzone2100-data"
else
  if ! ls "$work"/warzone2100-data_*.deb >/dev/null 2>&1; then
    (cd "$work" && apt-get download warzone2100-data)
  fi
  from=$(ls "$work"/warzone2100-data_*.deb | sed -n 1p)
  dpkg-deb -x "$from" "$work/x"
  base_wz=$(find "$work/x" -name base.wz | sed -n 1p)
fi
[[ -n "$base_wz" && -f "$base_wz" ]] || { echo "prepare-warzone: base.wz not found in $from" >&2; exit 1; }
rm -rf "$work/base"
unzip -q "$base_wz" -d "$work/base"
"$spinhash" prepare-warzone --base "$work/base" -o "$out/meshes"
echo "prepare-warzone: meshes in $out/meshes (catalog.csv lists them)"
