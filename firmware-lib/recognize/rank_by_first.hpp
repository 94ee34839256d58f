// The coarser rankings of an answer (classes, groups): each distinct key of
// the ranked models, scored by its first model in the ranking.
#pragma once
#include <cstdint>

#include "spinhash/recognizer.hpp"

namespace spinhash {

// The distinct keys (key_of(model index)) of r's ranking, each scored by its
// first model in the ranking, best first (ties by key), at most `capacity`
// of them (keys are ids below it). Ranked: {key, score, model, best_rank},
// its key the member `key`.
template <typename Ranked, typename KeyOf>
uint32_t rank_by_first_model(const Result& r, KeyOf key_of, uint32_t Ranked::*key, uint32_t capacity,
                             Ranked* out) {
  uint32_t n = 0;
  for (uint32_t k = 0; k < r.ranking_count && n < capacity; ++k) {
    const uint32_t id = key_of(r.ranking[k].model);
    uint32_t i = 0;
    while (i < n && out[i].*key != id) ++i;
    if (i < n) continue;  // ranked already, by a better model
    out[n++] = Ranked{id, r.ranking[k].score, r.ranking[k].model, k};
  }
  // Insertion sort of at most `capacity`: best first, ties by key.
  for (uint32_t i = 1; i < n; ++i)
    for (uint32_t j = i; j > 0; --j) {
      const Ranked& a = out[j - 1];
      const Ranked& b = out[j];
      if (a.score > b.score || (a.score == b.score && a.*key < b.*key)) break;
      const Ranked t = out[j - 1];
      out[j - 1] = out[j];
      out[j] = t;
    }
  return n;
}

}  // namespace spinhash
