#!/usr/bin/env bash
# Instructions per query over a whole set of scans on an emulated target: the
# mean, which sets a flight computer's load, beside the median and the worst.
#
#   scripts/instructions-over-set.sh [--models 56] [--spacings 0.05,0.10] [--seeds 11,12]
#       [--db DB] [--out DIR] [--target aarch64] [--target-build DIR] [--spinhash BIN]
#       [--set FIELD=VALUE]...
#
# The set: the first --models members of the procedural fleet, each scanned
# clean (no noise, no occlusion, 3 views, random pose) at every --spacings
# value with every --seeds seed. The database: --db, or the same members
# built by `spinhash build` with its calibration (a few minutes at 56
# models on 2 cores). Each scan is counted by DIR's cross-built
# tests/worst_case_runner (`query` mode, BRAN, the default config with each
# --set field) under qemu-user with scripts/qemu/insn_count.c, between the
# markers around the recognition. Writes DIR/instructions.csv (one row per
# scan; DIR: out/instructions-over-set, kept between runs: scans and
# database are made once) and prints the mean, the lower median, the worst,
# the queries the cascade's first pass answered alone and the right first
# answers.
set -euo pipefail
source "$(dirname "$0")/lib/ply_body.sh"
source "$(dirname "$0")/lib/qemu_count.sh"

usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

root=$(cd "$(dirname "$0")/.." && pwd)
models=56 spacings="0.05,0.10" seeds="11,12" db="" out="out/instructions-over-set" target=aarch64
target_build="$root/build-cross-aarch64" spinhash="$root/build/host-tools/spinhash"
settings=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --models) models="$2"; shift 2 ;;
    --spacings) spacings="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --db) db="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --target) target="$2"; shift 2 ;;
    --target-build) target_build="$2"; shift 2 ;;
    --spinhash) spinhash="$2"; shift 2 ;;
    --set) settings+=("$2"); shift 2 ;;
    *) usage ;;
  esac
done
runner="$target_build/tests/worst_case_runner"
for b in "$spinhash" "$runner"; do
  [[ -x "$b" ]] || { echo "instructions-over-set: missing $b" >&2; exit 1; }
done
mkdir -p "$out/members" "$out/scans"
qemu_count_setup instructions-over-set "$target" "$out"

[[ -n "$(ls "$out/members")" ]] || "$spinhash" generate -o "$out/members" --count "$models" 2>/dev/null
if [[ -z "$db" ]]; then
  db="$out/fleet.shdb"
  [[ -f "$db" ]] || "$spinhash" build -o "$db" "$out/members" --quiet
fi

IFS=, read -r -a spacing_list <<< "$spacings"
IFS=, read -r -a seed_list <<< "$seeds"
csv="$out/instructions.csv"
echo "scan,model,spacing,seed,top,passes,status,instructions" > "$csv"
for obj in "$out/members"/*.obj; do
  model=$(basename "$obj" .obj)
  for s in "${spacing_list[@]}"; do
    for seed in "${seed_list[@]}"; do
      name="${model}__${s}__${seed}"
      ply="$out/scans/$name.ply" raw="$out/scans/$name.f64"
      [[ -f "$ply" ]] || "$spinhash" scan "$obj" -o "$ply" --spacing "$s" --seed "$seed" --random-pose >/dev/null 2>&1
      [[ -f "$raw" ]] || ply_body "$ply" "$raw"
      line=$("${qemu[@]}" "$runner" query "$db" "$raw" bran "${settings[@]}" 2>&1) ||
        { echo "instructions-over-set: $name: $line" >&2; exit 1; }
      top=$(sed -n 's/.*top=\([^ ]*\).*/\1/p' <<< "$line")
      passes=$(sed -n 's/.*passes=\([0-9]*\).*/\1/p' <<< "$line")
      status=$(sed -n 's/.*status=\([a-z_ ]*[a-z]\).*/\1/p' <<< "$line" | head -1 | tr ' ' '_')
      insns=$(sed -n 's/^insns \([0-9]*\)$/\1/p' <<< "$line")
      [[ -n "$insns" && -n "$top" ]] || { echo "instructions-over-set: $name: no count in: $line" >&2; exit 1; }
      echo "$name,$model,$s,$seed,$top,$passes,$status,$insns" >> "$csv"
    done
  done
done

python3 - "$csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
counts = sorted(int(r["instructions"]) for r in rows)
n = len(counts)
first_alone = sum(r["passes"] == "1" for r in rows)
right = sum(r["top"] == r["model"] for r in rows)
print(f"| scans | mean (M) | median (M) | worst (M) | first pass alone | right first |")
print(f"|---:|---:|---:|---:|---:|---:|")
print(f"| {n} | {sum(counts) / n / 1e6:.1f} | {counts[(n - 1) // 2] / 1e6:.1f} | {counts[-1] / 1e6:.1f} "
      f"| {first_alone} | {right} |")
EOF
