#!/usr/bin/env bash
# The whole test suite, as CI runs it (.ci/run): installs what is missing,
# checks the layout and format rules (scripts/check_layout.sh), builds the
# Release tools and runs the experiment suites with ctest, then every onboard
# and hardening stage that scripts/ provides (cross targets under QEMU,
# sanitizers, fuzzing). The core and host suites are built twice, not three
# times: in Release for the cross targets (stages/20-cross.sh) and under the
# sanitizers on the host (stages/30-sanitizers.sh, every suite but the
# experiments'); the host Release build leaves them out to keep CI in time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)

scripts/install-deps.sh --cross

echo "== layout and format"
scripts/check_layout.sh

echo "== host build and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSPINHASH_SUITES=OFF >/dev/null
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

echo "== python module tests"
scripts/python-tests.sh build

# Further stages, each a script that exits non-zero on failure.
for stage in scripts/stages/*.sh; do
  [[ -e "$stage" ]] || continue
  echo "== $(basename "$stage" .sh)"
  bash "$stage"
done
echo "== all test stages passed"
