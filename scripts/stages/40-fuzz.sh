#!/usr/bin/env bash
# libFuzzer (clang, with ASan + UBSan): builds the `fuzz` preset in build-fuzz
# and runs each target for FUZZ_SECONDS from its seed corpus in fuzz/corpus/.
# New inputs go to build-fuzz/corpus/ (the repository's corpus stays as it
# is); a crash, leak, timeout or violated invariant fails the stage and leaves
# the input in build-fuzz/artifacts/ (printed in base64 too).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)
fuzz_seconds=${FUZZ_SECONDS:-45}
timeout_seconds=30      # one input taking longer is a hang (a normal one takes < 1 s under ASan)
recognize_max_len=8192  # bytes: above max_points (1024) as int16 triples, so thinning is reached
targets=(database_open cloud_reader las_reader laz_reader recognize)
start=$SECONDS

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$jobs"
built=$SECONDS

out=build-fuzz/runs
rm -rf "$out" build-fuzz/artifacts
mkdir -p "$out" build-fuzz/artifacts
pids=()
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t"
  extra=()
  [[ "$t" == recognize ]] && extra+=(-max_len="$recognize_max_len")
  # All targets at once: each gets a share of the cores for the same wall time.
  "build-fuzz/fuzz/fuzz_$t" -max_total_time="$fuzz_seconds" -timeout="$timeout_seconds" -print_final_stats=1 \
      -artifact_prefix="build-fuzz/artifacts/$t-" "${extra[@]}" "build-fuzz/corpus/$t" "fuzz/corpus/$t" \
      >"$out/$t.log" 2>&1 &
  pids+=($!)
done

failed=0
for i in "${!targets[@]}"; do
  t=${targets[$i]}
  if wait "${pids[$i]}"; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$t.log")
    echo "fuzz_$t: ${runs:-?} executions in ${fuzz_seconds} s, nothing found"
  else
    failed=1
    echo "fuzz_$t: FAILED, last lines of its log:"
    tail -n 40 "$out/$t.log"
  fi
done
for a in build-fuzz/artifacts/*; do
  [[ -e "$a" ]] || continue
  echo "artifact $a (base64): $(base64 -w0 "$a")"
done
echo "fuzz: build $((built - start)) s, runs $((SECONDS - built)) s"
exit "$failed"
