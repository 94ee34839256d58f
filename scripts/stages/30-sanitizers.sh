#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer: the `asan` preset of
# CMakePresets.json (RelWithDebInfo in build-asan, every target), then the
# whole ctest suite under it. Any report fails the stage: UBSan does not
# recover (-fno-sanitize-recover), ASan and LeakSanitizer abort.
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
