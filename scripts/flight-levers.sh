#!/usr/bin/env bash
# The flight trade-off: for each configuration of the recognizer, the
# aarch64 instructions per query (the instruction benchmark's queries under
# qemu-aarch64 with scripts/qemu/insn_count.c, as instructions-per-query.sh
# --target) beside its accuracy on the experiments' query sets, so that
# each lever's cost and saving are read off one table.
#
#   scripts/flight-levers.sh --configs FILE [--sizes 56] [--sets fleet,families]
#       [--family-seeds 1,2,3] [--out DIR] [--target-build DIR] [--spinhash BIN]
#       [--experiment BIN] [--only LABEL,...]
#
# FILE: one configuration a line, "LABEL [FIELD=VALUE ...]" (fields of
# include/spinhash/config.hpp by name; `default` with none is today's
# library default); # starts a comment. Each configuration is counted on the
# 6 benchmark queries (the first 3 fleet members scanned at 0.05 and 0.10 m,
# 5 cm noise, random pose, seeds 1-3) against the first --sizes members of
# the fleet, and run through `spinhash-experiment accuracy --set ...`:
#   fleet     56 models, 2 queries per model, 0.05 and 0.10 m: clean (no
#             noise, no occlusion) and 10 cm noise + 20 % occlusion with and
#             without 5-degree ground (the real cars' conditions)
#   families  the look-alike families: 3 queries per model, 5 cm noise, no
#             occlusion, 0.05 and 0.10 m, one run per --family-seeds seed
#   procedural1000  the first 1 000 fleet members, 100 queries from the
#             first 25 (`scaling --sizes 1000`), 0.05 and 0.10 m
#   lookalikes1000  17 models with 58 look-alike copies each (986 models),
#             2 queries per model, 5 cm noise, 0.05 and 0.10 m
# Results are kept per configuration (DIR/LABEL/...), so a second run only
# adds what is missing. Writes DIR/levers.csv (one row per configuration
# and size) and prints it as a Markdown table: instructions in millions
# (median of the 3 queries at each spacing, the lower middle of all 6, the
# worst), right first per set (the fleet's clean and noisy rows over both
# spacings, the families per spacing), confident answers that are right
# (fleet and families) and that are wrong (every set),
# and right-first answers gained and lost against `before` (the reference
# configuration of the FILE) on the same
# queries (every set both ran). DIR defaults to out/flight-levers (ignored by git).
set -euo pipefail
source "$(dirname "$0")/lib/fleet_db.sh"
source "$(dirname "$0")/lib/ply_body.sh"
source "$(dirname "$0")/lib/qemu_count.sh"

usage() { sed -n '2,36p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

root=$(cd "$(dirname "$0")/.." && pwd)
configs="" sizes="56" sets="fleet,families" seeds="1,2,3" out="out/flight-levers" only=""
target_build="$root/build-cross-aarch64"
spinhash="$root/build/host-tools/spinhash" experiment="$root/build/experiments/spinhash-experiment"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --configs) configs="$2"; shift 2 ;;
    --sizes) sizes="$2"; shift 2 ;;
    --sets) sets="$2"; shift 2 ;;
    --family-seeds) seeds="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --target-build) target_build="$2"; shift 2 ;;
    --spinhash) spinhash="$2"; shift 2 ;;
    --experiment) experiment="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    *) usage ;;
  esac
done
[[ -f "$configs" ]] || usage
runner="$target_build/tests/worst_case_runner"
for b in "$spinhash" "$experiment" "$runner"; do
  [[ -x "$b" ]] || { echo "flight-levers: missing $b" >&2; exit 1; }
done
qemu_count_setup flight-levers aarch64 "$out"

# The benchmark's queries and databases (instructions-per-stage.sh's).
spacings=(0.05 0.10)
if [[ ! -d "$out/first" ]]; then
  "$spinhash" generate -o "$out/first" --count 3 2>/dev/null
fi
mapfile -t first < <(ls "$out/first"/*.obj | sort)
for s in "${spacings[@]}"; do
  for q in 0 1 2; do
    ply="$out/q$q-$s.ply"
    [[ -f "$ply" ]] || "$spinhash" scan "${first[$q]}" -o "$ply" --noise 0.05 --spacing "$s" --random-pose --seed $((q + 1)) 2>/dev/null
    [[ -f "${ply%.ply}.f64" ]] || ply_body "$ply" "${ply%.ply}.f64"
  done
done
IFS=, read -r -a size_list <<< "$sizes"
for size in "${size_list[@]}"; do
  db="$out/db$size.shdb"
  fleet_db "$spinhash" "$db" "$size"
done

# Right first, confident and confident-wrong answers of per_query.csv files, by a key of columns.
tally() {  # KEYCOLS FILES...: prints "key right total confident_wrong" per key
  local keys=$1; shift
  awk -F, -v keys="$keys" 'FNR == 1 {for (i = 1; i <= NF; i++) col[$i] = i; next}
    {split(keys, k, "+"); key = ""; for (i = 1; i in k; i++) key = key (i > 1 ? "/" : "") $(col[k[i]])
     n[key]++; if ($(col["rank"]) == 1) r[key]++; if ($(col["confident"]) == 1 && $(col["rank"]) != 1) w[key]++}
    END {for (key in n) printf "%s %d %d %d\n", key, r[key], n[key], w[key]}' "$@" | sort
}

csv="$out/levers.csv"
echo "config,models,median_005,median_010,middle6,worst,fleet_clean,fleet_noisy,fleet_ground,families_005,families_010,lookalikes1000_005,lookalikes1000_010,procedural1000_005,procedural1000_010,confident_right,confident_wrong,paired,settings" > "$csv"
while read -r label rest; do
  [[ -z "$label" || "$label" == \#* ]] && continue
  [[ -n "$only" && ",$only," != *",$label,"* ]] && continue
  read -r -a settings <<< "${rest%%#*}"
  dir="$out/$label"
  mkdir -p "$dir"
  set_flags=()
  for s in "${settings[@]}"; do set_flags+=(--set "$s"); done

  # Accuracy (each run once per configuration).
  run_accuracy() {  # NAME ARGS...
    local name=$1; shift
    [[ -s "$dir/$name/per_query.csv" ]] && return 0
    echo "flight-levers: $label: accuracy $name" >&2
    "$experiment" accuracy --out "$dir/$name" --modes bran --max-k 5 "${set_flags[@]}" "$@" >"$dir/$name.log" 2>&1 ||
      { echo "flight-levers: $label: accuracy $name failed ($dir/$name.log)" >&2; exit 1; }
  }
  if [[ ",$sets," == *",fleet,"* ]]; then
    run_accuracy fleet-clean --queries-per-model 2 --noise 0 --occlusion 0 --spacing 0.05 0.1
    run_accuracy fleet-noisy --queries-per-model 2 --noise 0.1 --occlusion 0.2 --spacing 0.05 0.1 --ground --ground-slope 5
  fi
  if [[ ",$sets," == *",families,"* ]]; then
    IFS=, read -r -a seed_list <<< "$seeds"
    for seed in "${seed_list[@]}"; do
      run_accuracy "families-seed$seed" --seed "$seed" --models 56 --queries-per-model 3 --noise 0.05 --occlusion 0 --spacing 0.05 0.1
    done
  fi
  if [[ ",$sets," == *",procedural1000,"* ]]; then
    for sp in 0.05 0.10; do
      [[ -s "$dir/procedural1000-$sp/per_query.csv" ]] && continue
      echo "flight-levers: $label: scaling 1000 models, $sp m" >&2
      "$experiment" scaling --out "$dir/procedural1000-$sp" --sizes 1000 --queries 100 --modes bran --spacing "$sp" \
        "${set_flags[@]}" >"$dir/procedural1000-$sp.log" 2>&1 ||
        { echo "flight-levers: $label: scaling failed ($dir/procedural1000-$sp.log)" >&2; exit 1; }
    done
  fi
  if [[ ",$sets," == *",lookalikes1000,"* ]]; then
    run_accuracy lookalikes1000 --models 17 --lookalikes 58 --queries-per-model 2 --noise 0.05 --occlusion 0 --spacing 0.05 0.1
  fi
  acc() {  # GLOB FILTER-KEY: "right/total"
    local files=("$dir"/$1/per_query.csv)
    [[ -f "${files[0]}" ]] || { echo "-"; return; }
    tally "$2" "${files[@]}" | awk -v want="$3" '$1 == want {r += $2; n += $3} END {print (n ? r "/" n : "-")}'
  }
  clean=$(acc fleet-clean ground none)
  noisy=$(acc fleet-noisy ground none)
  ground=$(acc fleet-noisy ground scanned)
  fam005=$(acc "families-seed*" spacing 0.05)
  fam010=$(acc "families-seed*" spacing 0.1)
  la005=$(acc lookalikes1000 spacing 0.05)
  la010=$(acc lookalikes1000 spacing 0.1)
  p005=$(acc procedural1000-0.05 mode bran)
  p010=$(acc procedural1000-0.10 mode bran)
  wrong=$( (cat "$dir"/*/per_query.csv 2>/dev/null || true) | awk -F, '$0 ~ /(^|,)rank,/ {for (i = 1; i <= NF; i++) c[$i] = i; next}
    c["confident"] && $(c["confident"]) == 1 && $(c["rank"]) != 1 {w++} END {print w + 0}')

  # Confident and right over the fleet and families sets, and its share of the right answers.
  flagged=$( (cat "$dir"/fleet-*/per_query.csv "$dir"/families-*/per_query.csv 2>/dev/null || true) |
    awk -F, '$0 ~ /(^|,)rank,/ {for (i = 1; i <= NF; i++) c[$i] = i; next}
      $(c["rank"]) == 1 {r++; if ($(c["confident"]) == 1) f++} END {if (r) printf "%d (%.1f %%)", f, 100 * f / r; else print "-"}')

  # Paired with the default's answers on the same queries: right first gained and lost.
  paired=$(for f in "$dir"/*/per_query.csv; do
      [[ -f "$f" ]] || continue
      set_name=$(basename "$(dirname "$f")")
      base="$out/before/$set_name/per_query.csv"
      [[ -f "$base" ]] || continue
      awk -F, 'FNR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next}
        {key = ""; n = split("noise occlusion ground spacing model query", k, " ")
         for (i = 1; i <= n; i++) if (k[i] in c) key = key "," $(c[k[i]])
         right = $(c["rank"]) == 1}
        FILENAME == ARGV[1] {base[key] = right; next}
        key in base {if (right && !base[key]) g++; if (!right && base[key]) l++}
        END {print g + 0, l + 0}' "$base" "$f"
    done | awk '{g += $1; l += $2} END {print "+" g + 0 " -" l + 0}')

  # aarch64 instructions per size.
  for size in "${size_list[@]}"; do
    counts="$dir/insns.$size.txt"
    if [[ ! -s "$counts" ]]; then
      : > "$counts.tmp"
      for s in "${spacings[@]}"; do
        for q in 0 1 2; do
          echo "flight-levers: $label: $size models, $s m, query $q (qemu-aarch64)" >&2
          line=$("${qemu[@]}" "$runner" query "$out/db$size.shdb" "$out/q$q-$s.f64" bran "${settings[@]}" 2>&1)
          n=$(sed -n 's/.*insns \([0-9]*\).*/\1/p' <<< "$line")
          [[ -n "$n" ]] || { echo "flight-levers: $label: runner failed: $line" >&2; exit 1; }
          echo "$s $q $n $(grep -o 'top=[^ ]* hypotheses=[0-9]* features=[0-9]*' <<< "$line")" >> "$counts.tmp"
        done
      done
      mv "$counts.tmp" "$counts"
    fi
    read -r m005 m010 mid worst < <(awk '{v[$1, ++n[$1]] = $3; all[++k] = $3}
      function med(a, c,   i, j, t) {for (i = 2; i <= c; i++) {t = a[i]; j = i - 1; while (j >= 1 && a[j] > t) {a[j + 1] = a[j]; j--} a[j + 1] = t} return a[int((c + 1) / 2)]}
      END {for (i = 1; i <= 3; i++) {a5[i] = v["0.05", i]; a10[i] = v["0.10", i]}
           w = 0; for (i = 1; i <= k; i++) if (all[i] > w) w = all[i]
           printf "%.1f %.1f %.1f %.1f\n", med(a5, 3) / 1e6, med(a10, 3) / 1e6, med(all, k) / 1e6, w / 1e6}' "$counts")
    echo "$label,$size,$m005,$m010,$mid,$worst,$clean,$noisy,$ground,$fam005,$fam010,$la005,$la010,$p005,$p010,$flagged,$wrong,$paired,${settings[*]:-}" >> "$csv"
  done
done < "$configs"

echo "| config | models | M 0.05 | M 0.10 | M middle of 6 | M worst | fleet clean | fleet noisy | fleet noisy + ground | families 0.05 | families 0.10 | look-alikes 1000 0.05 | 0.10 | procedural 1000 0.05 | 0.10 | confident and right (of the right), fleet and families | confident wrong | right first gained / lost against before | settings |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
tail -n +2 "$csv" | awk -F, '{printf "|"; for (i = 1; i <= NF; i++) printf " %s |", $i; printf "\n"}'
