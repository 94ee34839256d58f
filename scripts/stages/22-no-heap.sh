#!/usr/bin/env bash
# onboard rule 1, docs/onboard-rules.md on every build of the core: host (./build, from
# scripts/test.sh), the three Linux cross builds and the bare-metal one.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
lib=firmware-lib/libspinhash_core.a
host_build=${SPINHASH_HOST_BUILD:-build}  # scripts/test.sh builds ./build
scripts/check_no_heap.sh nm "$host_build/$lib"
scripts/check_no_heap.sh aarch64-linux-gnu-nm build-cross-aarch64/$lib
scripts/check_no_heap.sh arm-linux-gnueabihf-nm build-cross-arm/$lib
scripts/check_no_heap.sh powerpc-linux-gnu-nm build-cross-powerpc/$lib
scripts/check_no_heap.sh arm-none-eabi-nm build-cross-cortex-m7/$lib
