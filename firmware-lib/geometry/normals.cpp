#include "geometry/normals.hpp"

#include <Eigen/Eigenvalues>

#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

bool normal_at(const CellGrid& grid, const float* points, const float* q, float radius, float* out) {
  // One pass: sums of offsets from q and of their outer products (offsets
  // from q, not from the origin, keep the float sums well conditioned). The
  // outer product is symmetric, so its six distinct sums are kept.
  float s[3] = {0.0f, 0.0f, 0.0f};
  float xx = 0.0f, xy = 0.0f, xz = 0.0f, yy = 0.0f, yz = 0.0f, zz = 0.0f;
  uint32_t count = 0;
  grid.for_each_within(q, radius, [&](uint32_t j) {
    const float* p = points + 3u * j;
    const float dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
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
  });
  if (count < kMinNormalNeighbours) return false;
  Eigen::Matrix3f outer;
  outer << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  const Eigen::Vector3f mean = Eigen::Map<const Eigen::Vector3f>(s) / static_cast<float>(count);
  const Eigen::Matrix3f cov = outer / static_cast<float>(count) - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver;
  solver.computeDirect(cov);                         // closed form: fixed cost, no iteration, no heap
  const Eigen::Vector3f& ev = solver.eigenvalues();  // ascending
  if (!(ev(2) > 0.0f) || ev(1) < kMinPlanarRatio * ev(2)) return false;
  Eigen::Vector3f nrm = solver.eigenvectors().col(0);
  float len = nrm.norm();
  if (!(len > 0.5f)) return false;
  nrm /= len;
  out[0] = nrm.x();
  out[1] = nrm.y();
  out[2] = nrm.z();
  return true;
}

}  // namespace

uint32_t estimate_normals(const CellGrid& grid, const float* points, uint32_t n, float radius, float* normals,
                          uint8_t* has_normal) {
  uint32_t good = 0;
  for (uint32_t i = 0; i < n; ++i) {
    bool ok = normal_at(grid, points, points + 3u * i, radius, normals + 3u * i);
    has_normal[i] = ok ? 1u : 0u;
    good += ok ? 1u : 0u;
  }
  return good;
}

void orient_normals(const float* points, uint32_t n, const float* reference, bool is_viewpoint,
                    float* normals, const uint8_t* has_normal) {
  for (uint32_t i = 0; i < n; ++i) {
    if (!has_normal[i]) continue;
    const float* p = points + 3u * i;
    float* nrm = normals + 3u * i;
    float s[3];  // the side the normal is turned to
    if (is_viewpoint) {
      for (int a = 0; a < 3; ++a) s[a] = reference[a] - p[a];
    } else if (nrm[2] >= kFacesUpZ || nrm[2] <= -kFacesUpZ) {
      s[0] = 0.0f, s[1] = 0.0f, s[2] = 1.0f;
    } else {
      s[0] = p[0] - reference[0], s[1] = p[1] - reference[1], s[2] = 0.0f;
    }
    if (nrm[0] * s[0] + nrm[1] * s[1] + nrm[2] * s[2] < 0.0f) {
      nrm[0] = -nrm[0];
      nrm[1] = -nrm[1];
      nrm[2] = -nrm[2];
    }
  }
}

}  // namespace spinhash
