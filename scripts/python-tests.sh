#!/usr/bin/env bash
# The Python module's pytest suite (tests/python/) against a build tree
# (default ./build): the module from BUILD/python/module, the interpreter it
# was built for, and the built `spinhash` command for the comparisons.
# "No tests collected" (pytest exit 5) is a failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
env_file=$build/python/python-env.sh
[[ -f "$env_file" ]] || { echo "python-tests: $env_file missing (SPINHASH_PYTHON off or not configured)"; exit 1; }
source "$env_file"
export PYTHONPATH=$SPINHASH_PYTHON_MODULE_DIR${PYTHONPATH:+:$PYTHONPATH}
export PYTHONDONTWRITEBYTECODE=1  # no __pycache__ in the source tree
export SPINHASH_CLI=$build/host-tools/spinhash SPINHASH_BUILD_DIR=$build
status=0
"$SPINHASH_PYTHON_EXECUTABLE" -m pytest -q -s -p no:cacheprovider "$root/tests/python" || status=$?
if [[ $status -eq 5 ]]; then
  echo "python-tests: no tests collected"
  exit 1
fi
exit $status
