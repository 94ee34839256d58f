# Sourced by the benchmark scripts: the database of N procedural vehicles
# (spinhash generate, then build), made once and kept in the output folder.
# fleet_db SPINHASH DB N
fleet_db() {
  local spinhash=$1 db=$2 size=$3 members
  [[ -f "$db" ]] && return 0
  members=$(mktemp -d)
  "$spinhash" generate -o "$members" --count "$size" 2>/dev/null
  "$spinhash" build -o "$db" "$members" --quiet
  rm -rf "$members"
}
