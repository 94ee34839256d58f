#!/usr/bin/env bash
# Installs what spinhash needs on Debian 12, idempotently: only the packages
# that are missing are installed. Pass --cross to add the cross toolchains
# and QEMU (needed by scripts/test.sh for the onboard checks), --cars to add
# the independent car meshes of scripts/prepare-cars.sh (torcs-data and
# trigger-rally-data: 450 MB to download, 650 MB installed; not in CI's
# default path: only the real-car experiments of docs/results.md read them).
set -euo pipefail

packages=(build-essential cmake doctest-dev libeigen3-dev libassimp-dev libembree-dev
          libcli11-dev gnuplot-nox
          libproj-dev libgdal-dev proj-bin gdal-bin  # the survey: GeoJSON in WGS 84, the GeoPackage (ogrinfo in the tests)
          zlib1g-dev  # the pictures' PNG compression
          pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest  # the Python module (python/)
          python3-dask python3-distributed python3-geopandas  # spinhash.survey on Dask (python/spinhash/survey.py)
          clang-format  # the layout check (scripts/check_layout.sh)
          clang libclang-rt-14-dev)  # libFuzzer and the sanitizer runtimes (scripts/stages/40-fuzz.sh)
for arg in "$@"; do
  if [[ "$arg" == "--cars" ]]; then packages+=(torcs-data trigger-rally-data unzip); fi
done
if [[ " $* " == *" --cross "* ]]; then
  packages+=(g++-aarch64-linux-gnu g++-arm-linux-gnueabihf g++-powerpc-linux-gnu
             gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-user
             valgrind python3)  # callgrind for the work budget, python3 for the stack report
  packages+=(pkgconf)  # pkg-config for the installed-package stage (scripts/stages/24-install.sh)
  packages+=(ccache)   # the installed-package stage's aarch64 core from the cross stage's objects
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
