#include "pipeline/segment_cell.hpp"

#include <cmath>

namespace spinhash::pipeline {

float segment_cell_for_density(float finest, double points_per_m2, double window_core) {
  if (!(points_per_m2 > 0.0) || !(finest > 0.0f)) return finest;
  const double spacing = 1.0 / std::sqrt(points_per_m2);
  double cell = finest;
  for (uint32_t k = 0; k < kMaxSegmentCellDoublings && cell < spacing; ++k) {
    const double cells = window_core / (2.0 * cell);
    if (std::fabs(cells - std::round(cells)) > 1e-6 * cells) break;
    cell *= 2.0;
  }
  return static_cast<float>(cell);
}

double tile_density(uint64_t points, double box_area) {
  return box_area > 0.0 ? static_cast<double>(points) / box_area : 0.0;
}

}  // namespace spinhash::pipeline
