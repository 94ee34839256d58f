#!/usr/bin/env bash
# Bare-metal Cortex-M7 (toolchains/arm-none-eabi.cmake): the core and the C
# API link into a main() with newlib nano and --gc-sections; reports code and
# data size and the worst stack chain of every entry point (from GCC's call
# graphs, scripts/stack_report.py) against docs/budgets.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
source scripts/budgets.sh
jobs=$(nproc 2>/dev/null || echo 2)
dir=build-cross-cortex-m7

# -fcallgraph-info=su writes the .ci call graphs next to the .su frame sizes;
# it comes in through CXXFLAGS so the toolchain's CPU flags stay.
CXXFLAGS=-fcallgraph-info=su cmake -S . -B "$dir" -DCMAKE_TOOLCHAIN_FILE=toolchains/arm-none-eabi.cmake \
  -DCMAKE_BUILD_TYPE=Release --no-warn-unused-cli >/dev/null
grep -q 'fcallgraph-info=su' "$dir/CMakeCache.txt" || { echo "bare-metal: $dir lacks -fcallgraph-info; delete it"; exit 1; }
# A configure that once failed (no cross compiler yet) caches empty Release
# flags: an unoptimised image ten times the size.
grep -q '^CMAKE_CXX_FLAGS_RELEASE:STRING=-O' "$dir/CMakeCache.txt" ||
  { echo "bare-metal: $dir caches no Release optimisation (an earlier configure failed?); delete it"; exit 1; }
cmake --build "$dir" -j"$jobs" >/dev/null

elf=$dir/examples/bare-metal/bare_metal_recognize.elf
arm-none-eabi-size "$elf" | sed 's/^/bare-metal: /'
arm-none-eabi-size -t "$dir/firmware-lib/libspinhash_core.a" | tail -n 1 |
  awk '{ print "bare-metal: libspinhash_core.a before --gc-sections: text " $1 ", data " $2 ", bss " $3 }'
read -r text data bss < <(arm-none-eabi-size "$elf" | awk 'NR == 2 { print $1, $2, $3 }')
blob=$(stat -c %s tests/golden/golden_le.shdb)
code=$((text - blob))  # .text + .rodata without the embedded database
echo "bare-metal: code+constants $code bytes (text $text - blob $blob), data $data, bss $bss (workspace + cloud)"
status=0
# Built with SPINHASH_NO_LOG_STRINGS: no log text may reach the image.
if arm-none-eabi-strings "$elf" | grep -q 'database open: '; then
  echo "bare-metal: log strings present despite SPINHASH_NO_LOG_STRINGS"; status=1
fi
code_budget=$(budget code.cortex-m7)
if (( code > code_budget )); then echo "bare-metal: code $code > budget $code_budget"; status=1; fi

stack_budget=$(budget stack.cortex-m7)
python3 scripts/stack_report.py "$dir" --budget "$stack_budget" | sed 's/^/bare-metal: /' || status=1
exit $status
