#!/bin/sh
# Generated tiles (make_scene_tile.py) of SIZE m with 5 fleet vehicles each
# (two side by side, one under a tree) among a building, a wall and a crate,
# through `spinhash scene`; prints per-tile detections against the truth.
# Usage: scripts/scene_experiment.sh SPINHASH FLEET_DIR FLEET.shdb OUT_DIR TILES [SLOPES]
set -eu
S=$1; FLEET=$2; DB=$3; OUT=$4; TILES=$5; SLOPES=${6:-"0 4 8 12"}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUT"
models=$(ls "$FLEET" | sed 's/\.obj$//')
t=0
while [ "$t" -lt "$TILES" ]; do
  for slope in $SLOPES; do
    t=$((t + 1))
    [ "$t" -gt "$TILES" ] && break
    picks=$(echo "$models" | python3 -c "import random,sys; m=sys.stdin.read().split(); random.Random($t).shuffle(m); print(' '.join(m[:5]))")
    files=""
    for m in $picks; do
      f="$OUT/${m}_t$t"
      nice "$S" scan "$FLEET/$m.obj" -o "$f.las" --views 4 --elevation 50 --noise 0.05 --spacing 0.1 --seed "$t" 2>/dev/null
      python3 "$HERE/las_class_filter.py" "$f.las" 1 "$f.xyz"
      files="$files $f.xyz"
    done
    nice python3 "$HERE/make_scene_tile.py" "$OUT/tile$t.xyz" "$OUT/truth$t.csv" "$slope" 50 $files 2>/dev/null
    nice "$S" scene --db "$DB" --top 3 "$OUT/tile$t.xyz" > "$OUT/tile$t.jsonl" 2> "$OUT/tile$t.err" || true
    python3 "$HERE/score_scene.py" "$OUT/truth$t.csv" "$OUT/tile$t.jsonl" "$slope" "$t"
  done
done
