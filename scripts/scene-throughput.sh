#!/usr/bin/env bash
# The scene path's throughput in points per second of one core, by stage
# (LAZ decoding, the along-track order, terrain, segmentation, the rest of
# the stream, recognition), on LAZ tiles: a dense one (toy vehicles at one
# per 300 m2 of sloped ground, tests/worst_case/stream_runner.cpp) and a
# sparse one (points spread at random over kilometres); then `spinhash
# scene` on the sparse tile end to end, and `spinhash survey` over sparse
# tiles, whose time follows their points, not their area.
#
#   scripts/scene-throughput.sh [--build DIR] [--out DIR] [--side 160] [--spacing 0.064]
#       [--sparse-points 1000] [--sparse-side 5000]
#
# Times are CPU seconds of the thread (the machine may be shared); the stages
# are timed by wrapping their calls (experiments/scene_throughput/). Writes
# DIR/throughput.csv and prints Markdown tables.
set -euo pipefail

usage() { sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build" out="scene-throughput-out" side=160 spacing=0.064 sparse_points=1000 sparse_side=5000
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --side) side="$2"; shift 2 ;;
    --spacing) spacing="$2"; shift 2 ;;
    --sparse-points) sparse_points="$2"; shift 2 ;;
    --sparse-side) sparse_side="$2"; shift 2 ;;
    *) usage ;;
  esac
done
runner="$build/tests/stream_runner" bench="$build/experiments/scene-throughput" cli="$build/host-tools/spinhash"
for tool in "$runner" "$bench" "$cli"; do
  [[ -x "$tool" ]] || { echo "scene-throughput: no $tool (build stream_runner, scene-throughput, spinhash)" >&2; exit 1; }
done
mkdir -p "$out"
out=$(cd "$out" && pwd)

echo "scene-throughput: the dense tile (${side} m at ${spacing} m, toy vehicles at one per 300 m2)" >&2
"$runner" prepare "$out" "$side" "$spacing" >&2
"$bench" laz "$out/strip.f64" "$out/dense.laz"
rm -f "$out/strip.f64"
echo "scene-throughput: the sparse tile ($sparse_points points over $sparse_side x $sparse_side m)" >&2
"$bench" sparse "$out/sparse.laz" "$sparse_points" "$sparse_side"

csv="$out/throughput.csv"
"$bench" run "$out/toy.shdb" "$out/dense.laz" "$out/sparse.laz" > "$csv"
echo "| tile | stage | CPU s | points per s per core |"
echo "| --- | --- | ---: | ---: |"
awk -F, 'NR > 1 {printf "| %s | %s | %.3f | %.2f M |\n", $1, $2, $3, $4 / 1e6}' "$csv"

# The whole command on the sparse tile (start included), and a survey of
# sparse tiles: 4 and then 16 tiles side by side, each like the sparse one.
cpu() { /usr/bin/time -f "%U %S" "$@" 2>&1 >/dev/null | tail -1 | awk '{printf "%.2f", $1 + $2}'; }
echo
echo "| run | points | CPU s (user + system) |"
echo "| --- | ---: | ---: |"
echo "| \`spinhash --version\` (the command's start) | 0 | $(cpu "$cli" --version) |"
echo "| \`spinhash scene\` on the sparse tile | $sparse_points | $(cpu "$cli" scene --db "$out/toy.shdb" "$out/sparse.laz") |"
for tiles in 4 16; do
  dir="$out/survey-$tiles"
  rm -rf "$dir" && mkdir -p "$dir/tiles"
  "$bench" sparse-tiles "$dir/tiles" "$tiles" "$sparse_points" "$sparse_side"
  echo "| \`spinhash survey\`, $tiles sparse tiles | $((tiles * sparse_points)) | $(cpu "$cli" survey --quiet --jobs 1 --db "$out/toy.shdb" --out "$dir/out" "$dir/tiles") |"
done
