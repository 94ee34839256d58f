// What every neighbour-moments kernel shares (the normals' PCA sums,
// geometry/normals.cpp): the sums themselves, the gathered neighbourhood
// they read (coordinates in separate arrays, as
// CellGrid::gather_neighbourhood lays them out), and the scalar arithmetic
// of one neighbour, which each SIMD lane repeats operation for operation
// (the core is built with -ffp-contract=off: no fused multiply-add), so that
// every kernel's sums are the reference's bit for bit.
#pragma once
#include <cstdint>

namespace spinhash {
namespace kernels {

// Sums of the offsets from a centre q of the points within the radius, and
// of their outer products (offsets from q, not from the origin, keep the
// float sums well conditioned; the outer product is symmetric, so its six
// distinct sums are kept). Added point by point in the neighbourhood's
// order: float addition is not associative.
struct NeighbourMoments {
  float s[3] = {0.0f, 0.0f, 0.0f};
  float xx = 0.0f, xy = 0.0f, xz = 0.0f, yy = 0.0f, yz = 0.0f, zz = 0.0f;
  uint32_t count = 0;
  void add(float dx, float dy, float dz) {
    s[0] += dx;
    s[1] += dy;
    s[2] += dz;
    xx += dx * dx;
    xy += dx * dy;
    xz += dx * dz;
    yy += dy * dy;
    yz += dy * dz;
    zz += dz * dz;
    ++count;
  }
};

// A gathered neighbourhood: count points' coordinates.
struct MomentsNeighbours {
  const float* x;
  const float* y;
  const float* z;
  uint32_t count;
};

// One gathered neighbour k: CellGrid::for_each_within's exact radius test
// (the same arithmetic), then its offset into the sums.
inline void moments_neighbour(const MomentsNeighbours& g, uint32_t k, const float* q, float r2,
                              NeighbourMoments* m) {
  const float ex = g.x[k] - q[0], ey = g.y[k] - q[1], ez = g.z[k] - q[2];
  if (ex * ex + ey * ey + ez * ez <= r2) m->add(ex, ey, ez);
}

}  // namespace kernels
}  // namespace spinhash
