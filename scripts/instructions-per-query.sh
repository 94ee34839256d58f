#!/usr/bin/env bash
# Instructions per query (valgrind --tool=callgrind: deterministic, unlike
# wall time on a shared machine) against database size, beside native wall
# time, for BRAN, SRAN and SIND on the same simulated queries.
#
#   scripts/instructions-per-query.sh [--sizes 56,1000] [--queries 3] [--modes bran,sran,sind]
#       [--sran-queries-large 1] [--spacing 0.05] [--out DIR] [--spinhash BIN]
#       [--preset default|flight|full] [--target aarch64|arm --target-build DIR]
#
# Counts cover Recognizer::run (feature extraction through ranking), not
# process start-up or database loading. SRAN is linear in the models and
# ~50x slower under callgrind: at sizes above 100 it runs only the first
# --sran-queries-large queries. --spacing: the queries' point spacing (m;
# 0.10 is an airborne sensor's at about 40 m). --preset: the recognizer's
# named configuration (include/spinhash/presets.hpp; default: the cascade).
# --target also counts each query on an
# emulated target: DIR's cross-built tests/worst_case_runner (`query` mode, the
# same default config) under qemu-user with scripts/qemu/insn_count.c, a TCG
# plugin that counts the instructions of the recognition (Debian ships no
# libinsn.so); it must rank the same model first. Writes DIR/instructions.csv
# (DIR: out/instructions unless given; git ignores out/) and prints a Markdown table of the means.
set -euo pipefail
source "$(dirname "$0")/lib/fleet_db.sh"
source "$(dirname "$0")/lib/ply_body.sh"
source "$(dirname "$0")/lib/qemu_count.sh"

usage() { sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

sizes="56,1000" queries=3 modes="bran,sran,sind" sran_large=1 out="out/instructions"
sran_large_from=100
noise=0.05 spacing=0.05
root=$(cd "$(dirname "$0")/.." && pwd)
spinhash="${SPINHASH:-}"
target="" target_build="" preset="default"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --queries) queries="$2"; shift 2 ;;
    --modes) modes="$2"; shift 2 ;;
    --sran-queries-large) sran_large="$2"; shift 2 ;;
    --spacing) spacing="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --spinhash) spinhash="$2"; shift 2 ;;
    --preset) preset="$2"; shift 2 ;;
    --target) target="$2"; shift 2 ;;
    --target-build) target_build="$2"; shift 2 ;;
    *) usage ;;
  esac
done
# The Release build scripts/test.sh makes (a sanitizer build counts its own instrumentation).
[[ -n "$spinhash" ]] || spinhash="$root/build/host-tools/spinhash"
[[ -x "$spinhash" ]] || { echo "instructions-per-query: no spinhash binary (--spinhash BIN)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "instructions-per-query: valgrind not installed" >&2; exit 1; }
mkdir -p "$out"
csv="$out/instructions.csv"
echo "models,features,mode,query,instructions,native_ms,hypotheses,top_model,true_model,target_instructions" > "$csv"

# The emulated target's count of one query (empty without --target).
target_count() {  # DB PLY MODE TOP HYPOTHESES
  [[ -n "$target" ]] || return 0
  local raw="${2%.ply}.f64"
  ply_body "$2" "$raw"
  local line
  line=$("${qemu[@]}" "$runner" query "$1" "$raw" "$3" "preset=$preset" 2>&1)
  # The target must rank the same model first. Its hypothesis count may
  # differ: libm's float results differ across targets, and with them a
  # few poses (docs/budgets.md); the count it drew is then said.
  [[ "$line" == *"top=$4 "* ]] ||
    { echo "instructions-per-query: $target ranks another model first: $line" >&2; exit 1; }
  [[ "$line" == *" hypotheses=$5 "* ]] ||
    echo "instructions-per-query: $target drew other hypotheses than the host ($5): ${line%%insns*}" >&2
  sed -n 's/.*insns \([0-9]*\).*/\1/p' <<< "$line"
}
if [[ -n "$target" ]]; then
  runner="$target_build/tests/worst_case_runner"
  [[ -x "$runner" ]] ||
    { echo "instructions-per-query: --target aarch64|arm needs --target-build DIR with tests/worst_case_runner" >&2; exit 1; }
  qemu_count_setup instructions-per-query "$target" "$out"
fi

IFS=, read -r -a size_list <<< "$sizes"
IFS=, read -r -a mode_list <<< "$modes"
# The same queries for every size, from the first fleet members (in every database).
"$spinhash" generate -o "$out/first" --count "$queries" 2>/dev/null
mapfile -t first < <(ls "$out/first"/*.obj | sort)
for ((q = 0; q < queries; q++)); do
  "$spinhash" scan "${first[$q]}" -o "$out/q$q.ply" --noise "$noise" --spacing "$spacing" --random-pose --seed $((q + 1)) 2>/dev/null
  basename "${first[$q]}" .obj > "$out/q$q.model"
done

for size in "${size_list[@]}"; do
  db="$out/db$size.shdb"
  fleet_db "$spinhash" "$db" "$size"
  # awk reads to the end: an early exit would break the pipe (pipefail).
  features=$("$spinhash" info "$db" | awk '$1 == "features" && !f {f = $2} END {print f}')
  for mode in "${mode_list[@]}"; do
    n=$queries
    [[ "$mode" == sran && $size -gt $sran_large_from && $sran_large -lt $n ]] && n=$sran_large
    for ((q = 0; q < n; q++)); do
      json=$("$spinhash" recognize --db "$db" --preset "$preset" --mode "$mode" --top 1 "$out/q$q.ply")
      ms=$(grep -o '"time_ms":[0-9.e+]*' <<< "$json" | cut -d: -f2)
      hyp=$(grep -o '"hypotheses":[0-9]*' <<< "$json" | sed -n 1p | cut -d: -f2)
      top=$(grep -o '"ranking":\[{"model":"[^"]*"' <<< "$json" | sed 's/.*"model":"//; s/"$//')
      cg="$out/callgrind.$size.$mode.$q"
      echo "instructions-per-query: $size models, $mode, query $q (callgrind)" >&2
      valgrind --tool=callgrind --toggle-collect='spinhash::Recognizer::run*' --callgrind-out-file="$cg" \
        "$spinhash" recognize --db "$db" --preset "$preset" --mode "$mode" --top 1 "$out/q$q.ply" >/dev/null 2>"$cg.log"
      ir=$(awk '/^(summary|totals):/ {print $2; exit}' "$cg")
      tir=$(target_count "$db" "$out/q$q.ply" "$mode" "$top" "$hyp")
      echo "$size,$features,$mode,$q,$ir,$ms,$hyp,$top,$(cat "$out/q$q.model"),$tir" >> "$csv"
    done
  done
done

echo "| models | mode | queries | mean instructions per query | mean native ms | mean on ${target:-no target} |"
echo "|---|---|---|---|---|---|"
awk -F, 'NR > 1 {k = $1 "," $3; n[k]++; ir[k] += $5; ms[k] += $6; t[k] += $10; if (!(k in seen)) {seen[k] = 1; order[++m] = k}}
  END {for (i = 1; i <= m; i++) {k = order[i]; split(k, a, ","); printf "| %s | %s | %d | %.4g | %.4g | %.4g |\n", a[1], a[2], n[k], ir[k] / n[k], ms[k] / n[k], t[k] / n[k]}}' "$csv"
