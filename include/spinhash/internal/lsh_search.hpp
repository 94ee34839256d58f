// Internal interface (host tools may use it; not installed, may change).
// Spin-image pruning (section 5): the W model features nearest (L1) to a
// query feature, from the joint LSH index (BRAN, SIND) or from one model's
// features exhaustively (SRAN).
#pragma once
#include <cstdint>

#include "spinhash/arena.hpp"
#include "spinhash/database.hpp"

namespace spinhash {

struct Candidate {
  uint32_t feature;   // database feature index
  uint32_t distance;  // L1, quantised units
};

// Inserts c into list[0, *count) kept sorted by (distance, feature), at most w long.
void insert_top_w(Candidate* list, uint32_t* count, uint32_t w, Candidate c);

struct SearchStats {
  uint64_t entries_scanned = 0;
  bool truncated = false;  // stopped at the scan bound
};

class LshSearcher {
 public:
  // Carves the seen set for searches of up to max_scan bucket entries; each
  // search scans that many until set_scan() lowers it.
  bool carve(Arena& arena, uint32_t max_scan);
  // The bucket entries each search looks at from now on, at most the carved max_scan.
  void set_scan(uint32_t scan);
  // Union of the query's L buckets, each distinct feature ranked by true
  // distance, best w kept; at most the set scan's bucket entries are looked at.
  uint32_t search(const Database& db, const uint8_t* spin, uint32_t w, Candidate* out, SearchStats* stats);

 private:
  bool mark_seen(uint32_t feature);
  uint32_t* seen_ = nullptr;   // open-addressing set of feature ids for this query
  uint32_t* stamp_ = nullptr;  // generation of each slot: no clearing between queries
  uint32_t capacity_ = 0;
  uint32_t slot_shift_ = 32;  // 32 - log2(capacity_): a product's top bits pick the slot
  uint32_t generation_ = 0;
  uint32_t max_scan_ = 0;  // the seen set's bound
  uint32_t scan_ = 0;      // this query's, at most max_scan_
};

// The w features of `model` nearest to spin, by exhaustive L1 scan.
uint32_t search_model_exhaustive(const Database& db, uint32_t model, const uint8_t* spin, uint32_t w,
                                 Candidate* out);

// Saliency (section 6): entropy (nats) of the per-model histogram of the
// candidates. Peaky (one model) = 0 = salient; flat over many models = high.
float candidate_entropy(const Database& db, const Candidate* list, uint32_t n);

}  // namespace spinhash
