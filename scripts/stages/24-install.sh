#!/usr/bin/env bash
# The installed package (docs/firmware.md, "Use it in your firmware"): runs
# every ```sh ci block of that page, in order, from the repository root:
# cmake --install of the host build into a fresh prefix, the outside project
# examples/consumer built against it with find_package and run on the golden
# data, pkg-config builds of the C and C++ examples, and the same for aarch64
# with only the toolchain file (run under qemu-user); the bare-metal core
# installs too. The page's commands are
# the tested ones; this script checks they still cover all of that and that
# the page's sample output is what the consumer prints.
# Reuses ./build (scripts/test.sh builds it); writes build-install/ (prefixes,
# log) and, afresh each run, build-aarch64, build-cortex-m7 and build-consumer*.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
start=$SECONDS
doc=docs/firmware.md
work=build-install
rm -rf "$work" build-aarch64 build-cortex-m7 build-consumer build-consumer-aarch64  # a clean machine's view (ccache keeps it quick)
mkdir -p "$work"
script=$work/firmware-doc.sh
log=$work/stage.log

awk '/^```sh ci$/ { on = 1; next } /^```/ { on = 0 } on' "$doc" >"$script"
# The page must keep showing (so CI keeps running) each acceptance step.
required=(
  'cmake --install build --prefix "$SPINHASH_PREFIX"'
  '-S examples/consumer -B build-consumer -DCMAKE_PREFIX_PATH'
  'pkg-config --cflags --libs spinhash'
  '-DCMAKE_TOOLCHAIN_FILE=toolchains/aarch64-linux-gnu.cmake'
  'cmake --install build-aarch64 --prefix "$SPINHASH_AARCH64_PREFIX"'
  'qemu-aarch64 -L /usr/aarch64-linux-gnu build-consumer-aarch64/recognize'
  'golden_query0.i16 toy-0'
  'cmake --install build-cortex-m7 --prefix "$SPINHASH_CORTEX_M7_PREFIX"'
)
for r in "${required[@]}"; do
  grep -qF -- "$r" "$script" || { echo "install: $doc has no '$r' in its sh ci blocks"; exit 1; }
done
# "The toolchain file alone": the cross configure must not switch the host tools off by hand.
if grep -q 'SPINHASH_HOST_TOOLS' "$script"; then echo "install: $doc sets SPINHASH_HOST_TOOLS"; exit 1; fi

export SPINHASH_PREFIX=$root/$work/prefix SPINHASH_AARCH64_PREFIX=$root/$work/prefix-aarch64 \
       SPINHASH_CORTEX_M7_PREFIX=$root/$work/prefix-cortex-m7
# ccache for the fresh aarch64 build (CMake takes launchers from the
# environment on a first configure only: ./build keeps its settings).
if command -v ccache >/dev/null; then
  export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
fi
if ! bash -euxo pipefail "$script" >"$log" 2>&1; then
  tail -n 40 "$log"
  echo "install: a command of $doc FAILED (full log: $log)"
  exit 1
fi

# What was installed: the public API without internal/, no research tool.
status=0
for f in lib/libspinhash_core.a include/spinhash/spinhash.h include/spinhash/recognizer.hpp \
         lib/cmake/spinhash/spinhashConfig.cmake lib/cmake/spinhash/spinhashConfigVersion.cmake \
         lib/pkgconfig/spinhash.pc bin/spinhash share/doc/spinhash/firmware.md; do
  [[ -e $SPINHASH_PREFIX/$f ]] || { echo "install: $f not installed"; status=1; }
done
for f in include/spinhash/internal bin/spinhash-experiment; do
  [[ ! -e $SPINHASH_PREFIX/$f ]] || { echo "install: $f must not be installed"; status=1; }
done
for p in "$SPINHASH_AARCH64_PREFIX" "$SPINHASH_CORTEX_M7_PREFIX"; do
  [[ -e $p/lib/libspinhash_core.a ]] || { echo "install: no core in $p"; status=1; }
  [[ ! -e $p/bin/spinhash ]] || { echo "install: host tools built in the cross build ($p)"; status=1; }
done
# The consumer's text reader, on the same query moved to UTM-sized coordinates
# (read as double: the pose must come back with the offset).
python3 - tests/golden/golden_query0.i16 >"$work/query0-utm.xyz" <<'PY'
import struct, sys
raw = open(sys.argv[1], "rb").read()
v = struct.unpack("<%dh" % (len(raw) // 2), raw)
print("# x y z (m): golden query 0 + (431000, 4020000, 85)")
for i in range(0, len(v), 3):
    print("%.3f %.3f %.3f" % (v[i] / 1000 + 431000, v[i + 1] / 1000 + 4020000, v[i + 2] / 1000 + 85))
PY
if ! build-consumer/recognize tests/golden/golden_le.shdb "$work/query0-utm.xyz" toy-0 >"$work/utm.log" 2>&1 ||
   ! grep -qE '^  1\. toy-0 .* t = \(4310[0-9][0-9]\.[0-9]+, 40199[0-9][0-9]\.[0-9]+, 8[56]\.' "$work/utm.log"; then
  cat "$work/utm.log"; echo "install: the consumer failed on the text query in UTM coordinates"; status=1
fi
cat "$work/utm.log" >>"$log"
# The page's sample output (its first console block, up to the "...") is
# what the native consumer printed; a change to recognition must update it.
expected=$(awk '/^```console$/ { on = 1; next } /^```/ { if (on) exit } on && !/^ *\.\.\.$/' "$doc")
actual=$(awk -v n="$(printf '%s\n' "$expected" | wc -l)" \
  '/^\+ build-consumer\/recognize tests/ { on = 1; next } on && /^\+/ { exit } on && n-- > 0' "$log")
if [[ "$expected" != "$actual" ]]; then
  echo "install: $doc's sample output is stale; the consumer now prints:"; printf '%s\n' "$actual"; status=1
fi
# Each run of the consumer printed its ranking; show the top lines.
grep -E '^  1\. |^  #1 ' "$log" | sed 's/^ */install: top: /'
echo "install: $(grep -c '^+ ' "$log") doc commands ran ($((SECONDS - start)) s)"
exit $status
