#!/usr/bin/env bash
# Layout and format rules (docs/onboard-rules.md, "Layout rules"), before
# anything is built:
#  1. no #include climbs out of its module with ../;
#  2. host code (host-tools, experiments, python, fuzz, examples) includes no
#     private core header (a path that exists under firmware-lib/): it uses
#     include/spinhash/ and include/spinhash/internal/;
#  3. host-tools never depends on experiments/; the pipeline every front end
#     shares has no CLI11 (the flags live in host-tools/flags/); blob/ (the
#     blob format) includes nothing of db/ (the database builder);
#  4. every C/C++ file is as .clang-format lays it out;
#  5. no tracked file tells the project's development history: no issue or
#     stop numbers (the word, a space or not, and a number), no citations of
#     the results' tuning rounds (results.md or "section" with a number and
#     a letter); say why, not when (git keeps the when);
#  6. no tracked file is over 1 MB (results and data stay out of the tree).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
status=0
sources=$(git ls-files '*.c' '*.h' '*.cpp' '*.hpp')

climbing=$(grep -nE '^\s*#\s*include\s+"(\.\./)+' $sources || true)
if [[ -n "$climbing" ]]; then
  echo "check_layout: includes that climb out of their module with ../:"; echo "$climbing"; status=1
fi

host_sources=$(git ls-files 'host-tools/*' 'experiments/*' 'python/*' 'fuzz/*' 'examples/*' | grep -E '\.(c|h|cpp|hpp)$' || true)
while IFS=: read -r file line include; do
  [[ -n "$file" ]] || continue
  header=$(sed -E 's/.*#\s*include\s+"([^"]+)".*/\1/' <<<"$include")
  if [[ -f "firmware-lib/$header" ]]; then
    echo "check_layout: $file:$line includes the core's private $header (use include/spinhash/internal/)"; status=1
  fi
done < <(grep -nE '^\s*#\s*include\s+"' $host_sources || true)

reverse=$(grep -nE '^\s*(#\s*include|[a-z_]+\().*experiments?/' host-tools/CMakeLists.txt \
            $(git ls-files 'host-tools/*' | grep -E '\.(cpp|hpp)$') || true)
if [[ -n "$reverse" ]]; then
  echo "check_layout: host-tools depends on experiments/:"; echo "$reverse"; status=1
fi

cli11=$(grep -nE '^\s*#\s*include\s+<CLI/' $(git ls-files 'host-tools/pipeline/*' | grep -E '\.(cpp|hpp)$') || true)
if [[ -n "$cli11" ]]; then
  echo "check_layout: the pipeline includes CLI11 (flags belong in host-tools/flags/):"; echo "$cli11"; status=1
fi
blob_db=$(grep -nE '^\s*#\s*include\s+"db/' $(git ls-files 'host-tools/blob/*' | grep -E '\.(cpp|hpp)$') || true)
if [[ -n "$blob_db" ]]; then
  echo "check_layout: blob/ includes db/:"; echo "$blob_db"; status=1
fi

if command -v clang-format >/dev/null; then
  if ! clang-format --dry-run --Werror $sources 2>/tmp/check_layout_format.txt; then
    echo "check_layout: files not laid out as .clang-format says (clang-format -i FILE):"
    grep -oE '^[^ :]+\.(c|h|cpp|hpp):[0-9]+:[0-9]+: (error|warning)' /tmp/check_layout_format.txt |
      cut -d: -f1 | sort -u | sed -n 1,40p
    status=1
  fi
else
  echo "check_layout: clang-format missing (scripts/install-deps.sh installs it)"; status=1
fi
# A number followed by a decimal point and a digit is a measure ("the scan
# stops" a decimal number of metres "short"), not a number of a stop.
history='\b([Ss]top|[Ii]ssue)s? [0-9]{1,3}\b(?!\.[0-9])|[Ss]top[0-9]{2}|[Ii]ssue[0-9]{2}'
rounds='results\.md[,:]?( section| §)? ?[0-9]{1,2}[a-z]?\b|\b[Ss]ections? [0-9]{1,2}[a-z]\b'
told=$( (git grep -InP "$history|$rounds" -- . ; git ls-files | grep -P "$history" | sed 's/$/: (the name)/') || true)
if [[ -n "$told" ]]; then
  echo "check_layout: development history in the tree (issue or stop numbers, results-round citations):"
  echo "$told" | cut -c1-200; status=1
fi

max_bytes=1000000
large=$(git ls-files -z | xargs -0 -r stat -c '%s %n' -- 2>/dev/null | awk -v max=$max_bytes '$1 > max' || true)
if [[ -n "$large" ]]; then
  echo "check_layout: tracked files over $max_bytes bytes (bytes, path):"; echo "$large"; status=1
fi

[[ $status -eq 0 ]] && echo "check_layout: includes stay in their modules; every file is formatted; no history; no file over 1 MB"
exit $status
