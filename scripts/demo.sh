#!/usr/bin/env bash
# Set-up and demo on built-in data: installs what is missing (Debian 12),
# builds, generates 56 procedural look-alike vehicles (8 families), compiles
# them into a database, simulates airborne 3-view scans of every vehicle
# (5 cm noise, random pose, georeferenced) and recognises them with batch
# RANSAC, then prints accuracy and time; ends with a small survey of 4 adjacent
# generated LAS tiles (spinhash survey). Everything lands in demo-out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
out=${DEMO_OUT:-demo-out}
vehicles=${DEMO_VEHICLES:-56}
scans_per_vehicle=${DEMO_SCANS:-2}
noise=${DEMO_NOISE:-0.05}

scripts/install-deps.sh
echo "== build"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target spinhash 2>&1 | tail -1
spinhash=build/host-tools/spinhash

rm -rf "$out" && mkdir -p "$out/queries"
echo "== $vehicles procedural vehicles"
$spinhash generate --count "$vehicles" -o "$out/fleet"
echo "== database"
$spinhash build -o "$out/fleet.shdb" "$out/fleet"
$spinhash info "$out/fleet.shdb" | sed -n 1,7p

echo "== $scans_per_vehicle airborne scans per vehicle (3 views, ${noise} m noise, random pose, UTM offset)"
seed=1
for mesh in "$out"/fleet/*.obj; do
  name=$(basename "$mesh" .obj)
  for i in $(seq 1 "$scans_per_vehicle"); do
    $spinhash scan "$mesh" -o "$out/queries/$name.q$i.ply" --noise "$noise" --seed $((seed++)) \
      --random-pose --offset 431000 4020000 85 2>/dev/null
  done
done

echo "== recognize (BRAN)"
$spinhash recognize --db "$out/fleet.shdb" --top 5 "$out"/queries/*.ply > "$out/results.jsonl"
head -c 400 "$out/results.jsonl"; echo " ..."

# Accuracy: the query "sedan-03.q1" is a scan of model "sedan-03".
median_ms=$(grep -o '"time_ms":[0-9.]*' "$out/results.jsonl" | cut -d: -f2 | sort -n |
            awk '{ t[NR] = $1 } END { print (NR % 2) ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2 }')
awk -v median="$median_ms" '
  match($0, /"query":"[^"]*"/) { q = substr($0, RSTART + 9, RLENGTH - 10); sub(/\.q[0-9]+$/, "", q) }
  { n++; split($0, parts, "\"model\":\""); first = parts[2]; sub(/".*/, "", first)
    top1 += (first == q); top5 += (index($0, "\"model\":\"" q "\"") > 0) }
  END { printf "%d queries: right model first %.1f%%, in the top 5 %.1f%%, median %.0f ms per query\n",
               n, 100 * top1 / n, 100 * top5 / n, median }' "$out/results.jsonl"

echo "== a small survey: an 80 m scene cut into 2 x 2 LAS tiles of 40 m, vehicles across the cuts"
$spinhash scan-scene "$out/fleet" -o "$out/survey-scene.las" --size 80 --vehicles 16 --trees 4 --seed 3 \
  --tiles-out "$out/survey-tiles" --tile-size 40 2>/dev/null
$spinhash survey --db "$out/fleet.shdb" --out "$out/survey" --quiet "$out/survey-tiles"
found=$(grep -c '"kind":"vehicle"' "$out/survey/detections.jsonl" || true)
# Each answer's "level": the most specific level whose flag it carries.
by_level=""
for level in model class group vehicle none; do
  n=$(grep -c "\"kind\":\"vehicle\".*\"level\":\"$level\"" "$out/survey/detections.jsonl" || true)
  by_level+="${by_level:+, }$level $n"
done
tiles=$(find "$out/survey-tiles" -name '*.las' | wc -l)
echo "survey: $found vehicles in $tiles tiles (answer level: $by_level);" \
     "GeoPackage $out/survey/detections.gpkg, picture $out/survey/overview.png"
