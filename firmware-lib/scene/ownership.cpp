#include <cmath>

#include "spinhash/scene_ownership.hpp"

namespace spinhash {
namespace {

// Distance from (x, y) to the closed rectangle of the area (0 inside or on an edge).
double distance_to(const OwnedArea& a, double x, double y) {
  const double dx = x < a.min[0] ? a.min[0] - x : (x > a.max[0] ? x - a.max[0] : 0.0);
  const double dy = y < a.min[1] ? a.min[1] - y : (y > a.max[1] ? y - a.max[1] : 0.0);
  return std::sqrt(dx * dx + dy * dy);
}

}  // namespace

bool area_holds(const OwnedArea& a, double x, double y) noexcept {
  return x >= a.min[0] && x < a.max[0] && y >= a.min[1] && y < a.max[1];
}

uint32_t owner_of(const OwnedArea* areas, uint32_t n, double x, double y, double tolerance) noexcept {
  if (areas == nullptr) return kNoOwner;
  for (uint32_t i = 0; i < n; ++i)
    if (area_holds(areas[i], x, y)) return i;
  uint32_t best = kNoOwner;
  double best_distance = tolerance;
  for (uint32_t i = 0; i < n; ++i) {
    const double d = distance_to(areas[i], x, y);
    if (d <= best_distance && (best == kNoOwner || d < best_distance)) {
      best = i;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace spinhash
