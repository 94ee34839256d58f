#!/usr/bin/env bash
# Instructions per input point of the scene stream, by stage, on the x86-64
# host (callgrind, inclusive counts) and on an emulated target (qemu-user
# with scripts/qemu/insn_count.c, counting between markers).
#
#   scripts/instructions-per-point.sh [--side 100] [--out DIR] [--host-build DIR]
#       [--target aarch64|arm --target-build DIR] [--preset default|flight]
#
# tests/worst_case/stream_runner.cpp writes a SIDE x SIDE m strip (0.1 m
# spacing, toy vehicles at one per 300 m2, scan order) and the toy database,
# then pushes the strip through SceneStream in 4 kB chunks and flushes. The
# count covers push and flush (not generation or loading). Stages: terrain
# (build_strip_terrain + terrain_heights), segmentation (segment_objects), recognition
# (Recognizer::recognize); "rest" is the stream's buffer, window gathering,
# object boxes, ownership and size gates (split on the host: rest_buffer,
# rest_gather, rest_objects). --preset: the recognizer's preset
# (include/spinhash/presets.hpp; the strip and every other field as
# default). Writes DIR/instructions-per-point.csv (DIR: out/instructions-per-point
# unless given; git ignores out/) and prints a Markdown table.
set -euo pipefail
source "$(dirname "$0")/lib/qemu_count.sh"

usage() { sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

root=$(cd "$(dirname "$0")/.." && pwd)
side=100 out="out/instructions-per-point" host_build="$root/build" target="" target_build="" preset=default
while [[ $# -gt 0 ]]; do
  case "$1" in
    --side) side="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --host-build) host_build="$2"; shift 2 ;;
    --target) target="$2"; shift 2 ;;
    --target-build) target_build="$2"; shift 2 ;;
    --preset) preset="$2"; shift 2 ;;
    *) usage ;;
  esac
done
runner="$host_build/tests/stream_runner"
[[ -x "$runner" ]] || { echo "instructions-per-point: no $runner (build target stream_runner)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "instructions-per-point: valgrind not installed" >&2; exit 1; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
stages=(terrain segmentation recognition)
# The stages' functions as callgrind names them (demangled).
declare -A functions=([cells]='spinhash::TerrainCells::sum(' [strip_terrain]='spinhash::build_strip_terrain('
                      [heights]='spinhash::terrain_heights('
                      [segmentation]='spinhash::segment_objects('
                      [recognition]='spinhash::Recognizer::recognize(float const*')

"$runner" prepare "$out" "$side"

# Host: callgrind, collecting inside push and flush only.
echo "instructions-per-point: x86-64 (callgrind)" >&2
cg="$out/callgrind.out"
host_line=$(valgrind --tool=callgrind --toggle-collect='spinhash::SceneStream::push*' \
  --toggle-collect='spinhash::SceneStream::flush*' --callgrind-out-file="$cg" "$runner" run "$out" "$preset" 2>"$cg.log")
declare -A host
host[total]=$(awk '/^(summary|totals):/ {print $2; exit}' "$cg")
annotated=$(callgrind_annotate --inclusive=yes --threshold=100 "$cg")
inclusive() {  # "  1,234 (12.3%)  file:function [object]": the first line naming the function
  grep -F "$1" <<< "$annotated" | grep -v '__wrap_' | sed -n 1p | awk '{gsub(",", "", $1); print $1}'
}
for s in cells strip_terrain heights segmentation recognition; do host[$s]=$(inclusive "${functions[$s]}"); done
host[terrain]=$(( host[cells] + host[strip_terrain] + host[heights] ))  # cell sums, strip grids, window heights
# The rest, split on the host only: into the frame and the buffer (push and
# flush less run_row), each window's points gathered from the buffer
# (run_row less run_window), and per window the object boxes, gathering and
# sorting of object points, ownership and size gates (run_window less the stages).
run_row=$(inclusive '::run_row(spinhash::StreamBuffers&')
run_window=$(inclusive 'spinhash::run_window(')
host[rest_buffer]=$(( host[total] - run_row ))
host[rest_gather]=$(( run_row - run_window - host[strip_terrain] - host[cells] ))
host[rest_objects]=$(( run_window - host[heights] - host[segmentation] - host[recognition] ))

# Target: qemu-user with the marker-counting plugin.
declare -A tgt
target_line=""
if [[ -n "$target" ]]; then
  target_runner="$target_build/tests/stream_runner"
  [[ -x "$target_runner" ]] ||
    { echo "instructions-per-point: --target aarch64|arm needs --target-build DIR with tests/stream_runner" >&2; exit 1; }
  qemu_count_setup instructions-per-point "$target" "$out" "${stages[@]/#/stage=}"
  echo "instructions-per-point: $target (qemu-$target, insn_count.so)" >&2
  raw=$("${qemu[@]}" "$target_runner" run "$out" "$preset" 2>&1)
  target_line=$(grep -o 'points=.*status=[a-z_]*' <<< "$raw")
  tgt[total]=$(sed -n 's/.*insns \([0-9]*\).*/\1/p' <<< "$raw")
  for s in "${stages[@]}"; do tgt[$s]=$(sed -n "s/.*insns\.$s \([0-9]*\).*/\1/p" <<< "$raw"); done
  # The same objects; hypothesis counts may differ (libm's last places move a few poses).
  [[ "${target_line%% hypotheses=*}" == "${host_line%% hypotheses=*}" ]] ||
    echo "instructions-per-point: $target reports other objects than the host:
  host:   $host_line
  $target: $target_line" >&2
fi

points=$(sed -n 's/^points=\([0-9]*\).*/\1/p' <<< "$host_line")
echo "host: $host_line"
[[ -z "$target" ]] || echo "$target: $target_line"
rest() {  # the total less the stages, from one of the arrays
  local -n a=$1
  [[ -n "${a[total]:-}" ]] || return 0
  echo $(( a[total] - a[terrain] - a[segmentation] - a[recognition] ))
}
host[rest]=$(rest host)
tgt[rest]=$(rest tgt)
csv="$out/instructions-per-point.csv"
echo "stage,points,x86_64_instructions,${target:-target}_instructions" > "$csv"
for s in total "${stages[@]}" rest rest_buffer rest_gather rest_objects; do
  echo "$s,$points,${host[$s]},${tgt[$s]:-}" >> "$csv"
done

echo "| stage | x86-64 instructions | per point | share | ${target:-target} instructions | per point | share |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
awk -F, 'NR == 2 {ht = $3; tt = $4}
  NR > 1 {
    hp = sprintf("%.0f", $3 / $2); hs = sprintf("%.1f %%", 100 * $3 / ht)
    if ($4 != "") {tp = sprintf("%.0f", $4 / $2); ts = sprintf("%.1f %%", 100 * $4 / tt)} else {tp = ""; ts = ""}
    printf "| %s | %.3g | %s | %s | %s | %s | %s |\n", $1, $3, hp, hs, ($4 != "" ? sprintf("%.3g", $4) : ""), tp, ts
  }' "$csv"
