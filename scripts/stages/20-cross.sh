#!/usr/bin/env bash
# Onboard proof (onboard rule 10, docs/onboard-rules.md): the core, its doctest suites, the C example
# and the bare-metal main cross-compiled for aarch64, armhf and big-endian
# powerpc, run under qemu-user through CMAKE_CROSSCOMPILING_EMULATOR.
# aarch64 (the flight target) runs every suite and every heavy case but the
# three "host-scale" ones, whose cost is the 40-copy database they build, not
# the target (the sanitizer build runs them on the host). armhf and powerpc run every
# suite but the heavy cases (label "heavy" in tests/CMakeLists.txt: each
# builds the toy database in-process and runs dozens of recognitions) and the
# float-heavy suites labelled "emulation-slow", which take minutes each under
# QEMU (powerpc floating point is emulated about 5x slower than aarch64) and
# run on aarch64 and, on the host, under the sanitizers. What the 32-bit and
# big-endian builds must prove stays on them: the golden vectors (the same
# recognition path), the blob in its byte order, the kernels, the C example.
# Builds in build-cross-<target>.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)
full_targets=${SPINHASH_FULL_CROSS_TARGETS:-aarch64}

declare -A triples=([aarch64]=aarch64-linux-gnu [arm]=arm-linux-gnueabihf [powerpc]=powerpc-linux-gnu)
for target in ${SPINHASH_CROSS_TARGETS:-aarch64 arm powerpc}; do
  triple=${triples[$target]}
  dir=build-cross-$target
  start=$SECONDS
  # aarch64 through ccache (depend mode: no preprocessing on a miss): the
  # installed-package stage builds the same core with the same flags, as
  # docs/firmware.md tells a user to, and then takes these objects.
  launch=()
  if [[ $target == aarch64 ]] && command -v ccache >/dev/null; then
    launch=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  cmake -S . -B "$dir" -DCMAKE_TOOLCHAIN_FILE="toolchains/$triple.cmake" -DCMAKE_BUILD_TYPE=Release --no-warn-unused-cli \
        -DSPINHASH_HOST_TOOLS=OFF "${launch[@]}" >/dev/null
  if ! CCACHE_DEPEND=true cmake --build "$dir" -j"$jobs" >"$dir/cross-build.log" 2>&1; then
    tail -n 40 "$dir/cross-build.log"
    echo "cross: $target build FAILED (full log: $dir/cross-build.log)"
    exit 1
  fi
  built=$SECONDS
  select=(-LE 'heavy|emulation-slow')
  [[ " $full_targets " == *" $target "* ]] && select=(-LE 'host-scale')
  log=$dir/cross-ctest.log
  if ! ctest --test-dir "$dir" --output-on-failure -j"$jobs" "${select[@]}" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "cross: $target FAILED (full log: $log)"
    exit 1
  fi
  grep -E '^(100% tests|Total Test time)' "$log" | sed "s/^/cross: $target: /"
  echo "cross: $target ok (build $((built - start)) s, tests $((SECONDS - built)) s${select:+, ${select[1]} left out})"
done
