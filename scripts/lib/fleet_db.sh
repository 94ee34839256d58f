# Sourced by the benchmark scripts: the database of N procedural vehicles
# (spinhash generate, then build), made once and kept in the output folder.
# Built without the flags' calibration: it costs build time (minutes at
# 1 000 models). Its flags are then the priors', and so is the cascade's
# stop after the first pass: a calibrated database's first-pass table may
# stop other queries there (docs/budgets.md measures both).
# fleet_db SPINHASH DB N
fleet_db() {
  local spinhash=$1 db=$2 size=$3 members
  [[ -f "$db" ]] && return 0
  members=$(mktemp -d)
  "$spinhash" generate -o "$members" --count "$size" 2>/dev/null
  "$spinhash" build -o "$db" "$members" --quiet --no-calibration
  rm -rf "$members"
}
