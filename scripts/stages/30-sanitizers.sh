#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer: the `asan` preset of
# CMakePresets.json (-O1 with asserts in build-asan, the suites' own code at
# -O0; every target but the experiments), then the whole ctest suite under
# it: the core suites (in Release they run under QEMU, stage 20) and the
# host tools' suites. The host's Release build (scripts/test.sh) runs the
# experiment suites. Any report fails the stage: UBSan does not recover
# (-fno-sanitize-recover), ASan and LeakSanitizer abort.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)
start=$SECONDS

cmake --preset asan >/dev/null
cmake --build --preset asan -j"$jobs"
built=$SECONDS
ctest --preset asan -j"$jobs"
echo "sanitizers: build $((built - start)) s, tests $((SECONDS - built)) s"
