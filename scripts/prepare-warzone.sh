#!/usr/bin/env bash
# Real artist-made models for the experiments: Warzone 2100's vehicles and
# structures (Debian package warzone2100-data, GPL game data: never commit
# it) as OBJ meshes.
#
#   scripts/prepare-warzone.sh (--deb FILE.deb | --wz base.wz | --download) -o DIR [--spinhash BIN]
#
# Unpacks base.wz (a zip) from the package, then runs
# `spinhash experiment prepare-warzone`, which reads the PIE models and
# writes DIR/vehicles/*.obj, DIR/structures/*.obj and DIR/catalog.csv.
# Then, e.g.:
#   spinhash experiment accuracy --meshes DIR/vehicles --out results/warzone
set -euo pipefail

usage() { sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

deb="" wz="" out="" download=0
root=$(cd "$(dirname "$0")/.." && pwd)
spinhash="${SPINHASH:-}"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --deb) deb="$2"; shift 2 ;;
    --wz) wz="$2"; shift 2 ;;
    --download) download=1; shift ;;
    -o|--output) out="$2"; shift 2 ;;
    --spinhash) spinhash="$2"; shift 2 ;;
    *) usage ;;
  esac
done
[[ -n "$out" && ( -n "$deb" || -n "$wz" || $download -eq 1 ) ]] || usage
if [[ -z "$spinhash" ]]; then
  for b in "$root"/build*/host-tools/spinhash; do [[ -x "$b" ]] && spinhash="$b" && break; done
fi
[[ -x "$spinhash" ]] || { echo "prepare-warzone: no spinhash binary (build it, or --spinhash BIN)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $download -eq 1 ]]; then
  (cd "$work" && apt-get download warzone2100-data >&2)
  deb=$(ls "$work"/warzone2100-data_*.deb)
fi
if [[ -n "$deb" ]]; then
  echo "prepare-warzone: unpacking $deb" >&2
  dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$work" ./usr/share/games/warzone2100/base.wz
  wz="$work/usr/share/games/warzone2100/base.wz"
fi
mkdir -p "$work/base"
unzip -q -o "$wz" 'components/*' 'structs/*' -d "$work/base"
"$spinhash" experiment prepare-warzone --base "$work/base" -o "$out"
