#include "geometry/normals.hpp"

#include <Eigen/Eigenvalues>

#include "kernels/moments_select.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

using Moments = kernels::NeighbourMoments;

// The normal of the moments' neighbourhood, if it is a surface.
bool normal_of(const Moments& m, float* out) {
  if (m.count < kMinNormalNeighbours) return false;
  Eigen::Matrix3f outer;
  outer << m.xx, m.xy, m.xz, m.xy, m.yy, m.yz, m.xz, m.yz, m.zz;
  const Eigen::Vector3f mean = Eigen::Map<const Eigen::Vector3f>(m.s) / static_cast<float>(m.count);
  const Eigen::Matrix3f cov = outer / static_cast<float>(m.count) - mean * mean.transpose();
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

bool normal_at(const CellGrid& grid, const float* points, const float* q, float radius, float* out) {
  Moments m;
  // Only where a gathered neighbourhood has no room: no culling (its code).
  grid.for_each_within<false>(q, radius, [&](uint32_t j) {
    const float* p = points + 3u * j;
    m.add(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  });
  return normal_of(m, out);
}

// The same test and sums over a neighbourhood gathered once for every
// point of a cell (CellGrid::gather_neighbourhood: the points for_each_within
// visits, in its order, plus those of the cells it skips as beyond the
// radius, which the test rejects), by the moments kernel
// (kernels/moments_select.hpp): the sums of the walk above, bit for bit.
bool normal_in(const NeighbourScratch& g, uint32_t count, const float* q, float r2, float* out) {
  Moments m;
  kernels::moments_accumulate(kernels::MomentsNeighbours{g.x, g.y, g.z, count}, q, r2, &m);
  return normal_of(m, out);
}

}  // namespace

uint32_t estimate_normals(const CellGrid& grid, const float* points, uint32_t n, float radius, float* normals,
                          uint8_t* has_normal, const NeighbourScratch& scratch) {
  uint32_t good = 0;
  auto set = [&](uint32_t i, bool ok) {
    has_normal[i] = ok ? 1u : 0u;
    good += ok ? 1u : 0u;
  };
  if (scratch.capacity == 0u || grid.cell_count() == 0u) {
    for (uint32_t i = 0; i < n; ++i)
      set(i, normal_at(grid, points, points + 3u * i, radius, normals + 3u * i));
    return good;
  }
  // Cell by cell (every point lies in one): the neighbourhood is gathered
  // once for all the cell's points; a neighbourhood beyond the scratch's
  // capacity is searched point by point as above.
  const float r2 = radius * radius;
  const int32_t reach = grid.reach_of(radius);
  const uint32_t* order = grid.order();
  for (uint32_t c = 0; c < grid.cell_count(); ++c) {
    const uint32_t first = grid.cell_first(c), size = grid.cell_size_of(c);
    const uint32_t gathered =
        grid.gather_neighbourhood(c, reach, scratch.x, scratch.y, scratch.z, scratch.capacity);
    for (uint32_t k = first; k < first + size; ++k) {
      const uint32_t i = order[k];
      const float* q = points + 3u * i;
      set(i, gathered == CellGrid::kGatherOverflow ? normal_at(grid, points, q, radius, normals + 3u * i)
                                                   : normal_in(scratch, gathered, q, r2, normals + 3u * i));
    }
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
