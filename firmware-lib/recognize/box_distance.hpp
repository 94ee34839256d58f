// How far apart two models' bounding boxes are, each in its own frame: the
// test of a look-alike that pose transfer and look-alike doublets share.
#pragma once
#include <cmath>

#include "spinhash/blob_format.hpp"

namespace spinhash {

// L1 distance over the boxes' 6 coordinates, m: small when the models'
// surfaces nearly coincide (same frame convention, nearly the same size).
inline float box_distance(const blob::ModelRecord& a, const blob::ModelRecord& b) {
  float d = 0.0f;
  for (int k = 0; k < 3; ++k)
    d += std::fabs(a.bbox_min[k] - b.bbox_min[k]) + std::fabs(a.bbox_max[k] - b.bbox_max[k]);
  return d;
}

}  // namespace spinhash
