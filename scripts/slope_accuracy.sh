#!/bin/sh
# Cut-out vehicles on ground tilted 0, 5, 10, 15 degrees against the same scans
# without their ground (the ground points removed by their LAS class).
# Usage: scripts/slope_accuracy.sh SPINHASH FLEET_DIR FLEET.shdb OUT_DIR [SLOPES]
# Writes OUT_DIR/slope_accuracy.csv: slope,ground,model,top1,confident,points_ground
set -eu
S=$1; FLEET=$2; DB=$3; OUT=$4; SLOPES=${5:-"0 5 10 15"}
mkdir -p "$OUT/q"
CSV="$OUT/slope_accuracy.csv"
echo "slope,ground,model,top1,confident,points_ground" > "$CSV"
for slope in $SLOPES; do
  i=0
  for mesh in "$FLEET"/*.obj; do
    i=$((i + 1))
    name=$(basename "$mesh" .obj)
    q="$OUT/q/${name}_s${slope}"
    nice "$S" scan "$mesh" -o "$q.las" --views 3 --noise 0.05 --ground 5 --ground-slope "$slope" --seed "$i" 2>/dev/null
    python3 "$(dirname "$0")/las_class_filter.py" "$q.las" 1 "$q.obj.xyz"
    for g in with without; do
      f="$q.las"; [ "$g" = without ] && f="$q.obj.xyz"
      nice "$S" recognize --db "$DB" --top 1 "$f" | python3 -c "
import json,sys
r=json.loads(sys.stdin.readline())
top=r['ranking'][0]['model'] if r['ranking'] else ''
print('$slope,$g,$name,%d,%d,%d' % (top=='$name', r.get('confident',False), r.get('stats',{}).get('points_ground',0)))" >> "$CSV"
    done
  done
done
