# Sourced by the onboard stages: reads a budget from docs/budgets.md, whose
# tables have rows "| `KEY` | measured | budget | ..." (numbers may use _ or ,).
budget() {
  local key=$1 file=${BUDGETS_FILE:-docs/budgets.md}
  local value
  value=$(awk -F'|' -v key="\`$1\`" '{ k = $2; gsub(/ /, "", k) } k == key { v = $4; gsub(/[ _,]/, "", v); print v; exit }' "$file")
  if [[ -z "$value" ]]; then
    echo "budgets: no row for \`$key\` in $file" >&2
    return 1
  fi
  echo "$value"
}
