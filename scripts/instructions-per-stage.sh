#!/usr/bin/env bash
# Instructions per query by stage (callgrind, inclusive counts inside
# Recognizer::run), BRAN, on the instruction benchmark's queries (the same as
# scripts/instructions-per-query.sh: the first --queries fleet members,
# scanned with 0.05 m noise at each --spacings value, random pose, seeds
# 1..N) against fleets of each --sizes models:
#
#   scripts/instructions-per-stage.sh [--sizes 17,56,1000] [--queries 3] [--spacings 0.05,0.10]
#       [--out DIR] [--spinhash BIN] [--jobs N] [--check] [--reuse]
#
# Stages: features (extract_stage: the cloud, normals and spin images), lsh (LshSearcher::search),
# verification (verify_pose, hypotheses and finalisation alike, with its
# nearest-feature lookups), rest (the total less those: doublets, poses,
# ranking, refinement's least squares). Writes DIR/stages.csv (out/stages) and prints,
# per size and stage, the median and the worst query (Markdown). --check
# compares them with the `stage.<size>.<stage>.median` and `.worst` rows of
# docs/budgets.md (scripts/budgets.sh) and fails over budget. --reuse keeps
# the callgrind files DIR already holds (the same binary's).
set -euo pipefail
source "$(dirname "$0")/lib/fleet_db.sh"

usage() { sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

sizes="17,56,1000" queries=3 spacings="0.05,0.10" out="out/stages" jobs=2 check=0 reuse=""
noise=0.05
root=$(cd "$(dirname "$0")/.." && pwd)
spinhash="${SPINHASH:-}"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --queries) queries="$2"; shift 2 ;;
    --spacings) spacings="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --spinhash) spinhash="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --check) check=1; shift ;;
    --reuse) reuse=1; shift ;;
    *) usage ;;
  esac
done
# The Release build scripts/test.sh makes (a sanitizer build counts its own instrumentation).
[[ -n "$spinhash" ]] || spinhash="$root/build/host-tools/spinhash"
[[ -x "$spinhash" ]] || { echo "instructions-per-stage: no spinhash binary (--spinhash BIN)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "instructions-per-stage: valgrind not installed" >&2; exit 1; }
mkdir -p "$out"

IFS=, read -r -a size_list <<< "$sizes"
IFS=, read -r -a spacing_list <<< "$spacings"
"$spinhash" generate -o "$out/first" --count "$queries" 2>/dev/null
mapfile -t first < <(ls "$out/first"/*.obj | sort)
for s in "${spacing_list[@]}"; do
  for ((q = 0; q < queries; q++)); do
    "$spinhash" scan "${first[$q]}" -o "$out/q$q-$s.ply" --noise "$noise" --spacing "$s" --random-pose --seed $((q + 1)) 2>/dev/null
  done
done

# One query under callgrind: "total features lsh verification top".
count_stages() {  # DB PLY CGFILE
  local cg=$3
  [[ -n "$reuse" && -s "$cg" && -s "$cg.json" ]] ||
    valgrind --tool=callgrind --toggle-collect='spinhash::Recognizer::run*' --callgrind-out-file="$cg" \
    "$spinhash" recognize --db "$1" --mode bran --top 1 "$2" >"$cg.json" 2>"$cg.log"
  local total top
  total=$(awk '/^(summary|totals):/ {print $2; exit}' "$cg")
  callgrind_annotate --inclusive=yes --threshold=100 "$cg" 2>/dev/null > "$cg.txt"
  incl() { grep -F "$1" "$cg.txt" | sed -n 1p | awk '{gsub(",", "", $1); print $1 + 0}'; }
  top=$(grep -o '"ranking":\[{"model":"[^"]*"' "$cg.json" | sed 's/.*"model":"//; s/"$//')
  echo "$total $(incl 'spinhash::extract_stage(') $(incl 'LshSearcher::search(') $(incl 'spinhash::verify_pose(') ${top:-none}"
}
export -f count_stages
export spinhash reuse

csv="$out/stages.csv"
echo "models,spacing,query,total,features,lsh,verification,rest,top" > "$csv"
for size in "${size_list[@]}"; do
  db="$out/db$size.shdb"
  fleet_db "$spinhash" "$db" "$size"
  # The queries of one size, --jobs at a time (counts do not depend on the load).
  pids=()
  for s in "${spacing_list[@]}"; do
    for ((q = 0; q < queries; q++)); do
      echo "instructions-per-stage: $size models, $s m, query $q (callgrind)" >&2
      (count_stages "$db" "$out/q$q-$s.ply" "$out/callgrind.$size.$s.$q" > "$out/stages.$size.$s.$q") &
      pids+=($!)
      if (( ${#pids[@]} >= jobs )); then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
    done
  done
  wait
  for s in "${spacing_list[@]}"; do
    for ((q = 0; q < queries; q++)); do
      read -r total f l v top < "$out/stages.$size.$s.$q"
      [[ "$total$f$l$v" =~ ^[0-9]+$ ]] ||
        { echo "instructions-per-stage: a counted function is missing from $out/callgrind.$size.$s.$q.txt" >&2; exit 1; }
      echo "$size,$s,$q,$total,$f,$l,$v,$((total - f - l - v)),$top" >> "$csv"
    done
  done
done

# Median (lower middle of an even count) and worst per size and stage, in millions.
summary=$(awk -F, 'NR > 1 {n[$1]++; for (c = 4; c <= 8; c++) v[$1, c, n[$1]] = $c + 0; if (!($1 in seen)) {seen[$1] = 1; order[++m] = $1}}
  END {
    split("total features lsh verification rest", name, " ")
    for (i = 1; i <= m; i++) { s = order[i]
      for (c = 4; c <= 8; c++) {
        k = n[s]; for (j = 1; j <= k; j++) a[j] = v[s, c, j]
        for (x = 2; x <= k; x++) { t = a[x]; y = x - 1; while (y >= 1 && a[y] > t) { a[y + 1] = a[y]; y-- } a[y + 1] = t }
        printf "%s %s %d %d\n", s, name[c - 3], a[int((k + 1) / 2)], a[k] } } }' "$csv")
echo "| models | stage | median (M) | worst (M) | worst / median |"
echo "|---|---|---:|---:|---:|"
while read -r size stage median worst; do
  awk -v s="$size" -v g="$stage" -v m="$median" -v w="$worst" \
    'BEGIN {printf "| %s | %s | %.1f | %.1f | %.2fx |\n", s, g, m / 1e6, w / 1e6, (m > 0 ? w / m : 0)}'
done <<< "$summary"

if (( check )); then
  cd "$root"
  source scripts/budgets.sh
  status=0
  while read -r size stage median worst; do
    for kind in median worst; do
      measured=$median; [[ $kind == worst ]] && measured=$worst
      key="stage.$size.$stage.$kind"
      limit=$(budget "$key") || { status=1; continue; }
      verdict=ok
      (( measured <= limit )) || { verdict="OVER BUDGET"; status=1; }
      printf 'stage-budget: %-32s %12s instructions (budget %s) %s\n' "$key" "$measured" "$limit" "$verdict"
    done
  done <<< "$summary"
  exit $status
fi
