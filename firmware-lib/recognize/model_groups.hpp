// A query feature's candidate list grouped by model: BRAN's draw pairs only
// candidates of one model (the paper's W_k x W_l same-model pairs), and with
// the groups it visits exactly those pairs, in the order of the loop over
// all W x W pairs, without stepping over the other models' candidates (800
// draws of a 1 000-feature query: 2 M pairs looked at, some 26 M
// instructions, for a few thousand of one model).
#pragma once
#include <cstdint>

#include "spinhash/internal/lsh_search.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {

struct ModelGroups {
  uint16_t model[kMaxCandidates];  // ascending; equal models in list order
  uint8_t index[kMaxCandidates];   // the candidate's place in its list (W <= kMaxCandidates <= 256)
  uint32_t count = 0;
};
static_assert(kMaxCandidates <= 256u, "ModelGroups::index holds a list position in a byte");

// A stable insertion sort of the n (<= kMaxCandidates) candidates' places by model.
inline void group_by_model(const Candidate* list, uint32_t n, const uint16_t* feature_models,
                           ModelGroups* g) {
  g->count = n;
  for (uint32_t i = 0; i < n; ++i) {
    const uint16_t m = feature_models[list[i].feature];
    uint32_t j = i;
    for (; j > 0 && g->model[j - 1u] > m; --j) {
      g->model[j] = g->model[j - 1u];
      g->index[j] = g->index[j - 1u];
    }
    g->model[j] = m;
    g->index[j] = static_cast<uint8_t>(i);
  }
}

// The first group entry of model m or above (binary search: log2 W steps).
inline uint32_t first_of_model(const ModelGroups& g, uint16_t m) {
  uint32_t lo = 0, hi = g.count;
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo) / 2u;
    if (g.model[mid] < m)
      lo = mid + 1u;
    else
      hi = mid;
  }
  return lo;
}

}  // namespace spinhash
