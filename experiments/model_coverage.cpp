#include "model_coverage.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace spinhash::experiment {
namespace {

// Query points hashed by kCoverageRadius cells: a feature looks in its cell's
// 27 neighbours. The key keeps 21 bits per axis: cells that collide (525 km
// apart) only cost distance checks.
struct PointGrid {
  std::unordered_map<int64_t, std::vector<uint32_t>> cells;
  const std::vector<double>* xyz = nullptr;
  static int64_t key(int64_t x, int64_t y, int64_t z) {
    return ((x & 0x1FFFFF) << 42) | ((y & 0x1FFFFF) << 21) | (z & 0x1FFFFF);
  }
  static int64_t cell(double v) { return static_cast<int64_t>(std::floor(v / kCoverageRadius)); }
  explicit PointGrid(const std::vector<double>& points) : xyz(&points) {
    for (uint32_t i = 0; 3u * i + 2u < points.size(); ++i)
      cells[key(cell(points[3 * i]), cell(points[3 * i + 1]), cell(points[3 * i + 2]))].push_back(i);
  }
  bool near(const double* p) const {
    const double r2 = static_cast<double>(kCoverageRadius) * kCoverageRadius;
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(key(cell(p[0]) + dx, cell(p[1]) + dy, cell(p[2]) + dz));
          if (it == cells.end()) continue;
          for (uint32_t i : it->second) {
            const double* q = xyz->data() + 3u * i;
            const double d2 =
                (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]);
            if (d2 <= r2) return true;
          }
        }
    return false;
  }
};

}  // namespace

float model_coverage(const Database& db, uint32_t model, const Pose& pose, const std::vector<double>& xyz) {
  const blob::ModelRecord& m = db.model(model);
  const PointGrid grid(xyz);
  const float* f = db.positions() + 3u * static_cast<size_t>(m.first_feature);
  uint32_t above = 0, covered = 0;
  for (uint32_t i = 0; i < m.feature_count; ++i) {
    const float* x = f + 3u * i;
    if (x[2] <= m.bbox_min[2] + kCoverageBand) continue;
    double p[3];
    for (int r = 0; r < 3; ++r)
      p[r] = pose.rotation[3 * r] * x[0] + pose.rotation[3 * r + 1] * x[1] + pose.rotation[3 * r + 2] * x[2] +
             pose.translation[r];
    ++above;
    covered += grid.near(p) ? 1u : 0u;
  }
  return above ? static_cast<float>(covered) / static_cast<float>(above) : 0.0f;
}

}  // namespace spinhash::experiment
