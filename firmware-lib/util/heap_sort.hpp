// Non-recursive, allocation-free heapsort: O(n log n) worst case with a
// bounded loop count, for rankings whose length is only known at run time.
#pragma once
#include <cstdint>

namespace spinhash {

// Sorts items[0, n) so that less(items[i], items[j]) holds for i < j (for a
// strict weak order with no equal elements the result is fully determined).
template <typename T, typename Less>
void heap_sort(T* items, uint32_t n, Less less) {
  auto sift_down = [&](uint32_t root, uint32_t end) {
    for (uint32_t guard = 0; guard < 32u; ++guard) {  // depth <= log2(2^32)
      uint32_t child = 2u * root + 1u;
      if (child >= end) return;
      if (child + 1u < end && less(items[child], items[child + 1u])) ++child;
      if (!less(items[root], items[child])) return;
      T tmp = items[root];
      items[root] = items[child];
      items[child] = tmp;
      root = child;
    }
  };
  if (n < 2u) return;
  for (uint32_t i = n / 2u; i-- > 0u;) sift_down(i, n);
  for (uint32_t end = n - 1u; end > 0u; --end) {
    T tmp = items[0];
    items[0] = items[end];
    items[end] = tmp;
    sift_down(0u, end);
  }
}

}  // namespace spinhash
