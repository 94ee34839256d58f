#!/usr/bin/env bash
# onboard rule 1, docs/onboard-rules.md: the core archive references no allocator and no exception
# machinery. Usage: scripts/check_no_heap.sh NM LIBSPINHASH_CORE.a [...]
# (NM is the target's nm, e.g. aarch64-linux-gnu-nm). Placement new is inline
# and leaves no symbol, so any operator new/delete reference is a real one.
set -euo pipefail
nm_tool=$1
shift
forbidden='^(malloc|calloc|realloc|free|aligned_alloc|posix_memalign|memalign|operator new|operator delete|__cxa_throw|__cxa_allocate_exception|__cxa_begin_catch|__cxa_rethrow|_Unwind_Resume)(\(|$)'
status=0
for lib in "$@"; do
  [[ -f "$lib" ]] || { echo "no-heap: $lib missing"; status=1; continue; }
  # Undefined and defined symbols alike: a definition would be an allocator in the core.
  hits=$("$nm_tool" -C "$lib" 2>/dev/null | awk '{ $1 = ($1 ~ /^[0-9a-f]+$/) ? "" : $1; sub(/^ *[A-Za-z] /, ""); sub(/^ +/, ""); print }' \
         | grep -E "$forbidden" | sort -u || true)
  if [[ -n "$hits" ]]; then
    echo "no-heap: FAIL $lib references:"
    sed 's/^/    /' <<< "$hits"
    status=1
  else
    echo "no-heap: ok   $lib"
  fi
done
exit $status
