// How far apart two models' bounding boxes are, each in its own frame, and
// the models nearest one by box: the test of a look-alike that pose
// transfer, the final lending and look-alike doublets share.
#pragma once
#include <cmath>

#include "spinhash/blob_format.hpp"
#include "spinhash/database.hpp"
#include "util/top_n.hpp"

namespace spinhash {

// The two boxes' L1 difference along axis k (both ends), m.
inline float box_axis_l1(const blob::ModelRecord& a, const blob::ModelRecord& b, int k) {
  return std::fabs(a.bbox_min[k] - b.bbox_min[k]) + std::fabs(a.bbox_max[k] - b.bbox_max[k]);
}

// L1 distance over the boxes' 6 coordinates, m: small when the models'
// surfaces nearly coincide (same frame convention, nearly the same size).
inline float box_distance(const blob::ModelRecord& a, const blob::ModelRecord& b) {
  float d = 0.0f;
  for (int k = 0; k < 3; ++k) d += box_axis_l1(a, b, k);
  return d;
}

// Whether box_distance(a, b) <= limit, stopping once the sum is past it:
// the same sum in the same order, so the same answer. Most pairs of spread
// candidates are of other families and fail on the first axis.
inline bool boxes_within(const blob::ModelRecord& a, const blob::ModelRecord& b, float limit) {
  float d = 0.0f;
  for (int k = 0; k < 3; ++k) {
    d += box_axis_l1(a, b, k);
    if (d > limit) return false;
  }
  return d <= limit;  // false for NaN too, as box_distance's comparison
}

// Writes to out[0, n) up to `wanted` models that `keep` accepts, nearest
// `source` by box first (ties by index); returns n. The look-alikes a pose
// is lent to.
template <typename Keep>
uint32_t nearest_by_box(const Database& db, uint32_t source, uint32_t wanted, uint32_t* out, Keep keep) {
  const blob::ModelRecord& src = db.model(source);
  return top_n(db.model_count(), wanted, out, keep, [&](uint32_t a, uint32_t b) {
    const float da = box_distance(src, db.model(a)), d_b = box_distance(src, db.model(b));
    return da < d_b || (da == d_b && a < b);
  });
}

}  // namespace spinhash
