#include "geometry/terrain.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>

#include "util/fixed_math.hpp"

namespace spinhash {
namespace {

constexpr float kEmptyCell = 3.0e38f;  // lowest point of a cell without points
constexpr uint32_t kMinPlaneCells = 3;

struct Grid {
  float x0 = 0.0f, y0 = 0.0f, cell = kMinTerrainCell;
  uint32_t cell_of(const float* p) const {
    int32_t i = static_cast<int32_t>((p[0] - x0) / cell), j = static_cast<int32_t>((p[1] - y0) / cell);
    const int32_t last = static_cast<int32_t>(kTerrainGridSide) - 1;
    i = i < 0 ? 0 : (i > last ? last : i);
    j = j < 0 ? 0 : (j > last ? last : j);
    return static_cast<uint32_t>(j) * kTerrainGridSide + static_cast<uint32_t>(i);
  }
  float centre_x(uint32_t c) const { return x0 + (static_cast<float>(c % kTerrainGridSide) + 0.5f) * cell; }
  float centre_y(uint32_t c) const { return y0 + (static_cast<float>(c / kTerrainGridSide) + 0.5f) * cell; }
};

struct Plane {
  float a = 0.0f, b = 0.0f, c = 0.0f;  // z = a x + b y + c
  float at(float x, float y) const { return a * x + b * y + c; }
};

Grid footprint(const float* xyz, uint32_t n) {
  float lo[2] = {xyz[0], xyz[1]}, hi[2] = {xyz[0], xyz[1]};
  for (uint32_t i = 1; i < n; ++i)
    for (uint32_t a = 0; a < 2; ++a) {
      const float v = xyz[3u * i + a];
      lo[a] = v < lo[a] ? v : lo[a];
      hi[a] = v > hi[a] ? v : hi[a];
    }
  Grid g;
  g.x0 = lo[0];
  g.y0 = lo[1];
  const float extent = hi[0] - lo[0] > hi[1] - lo[1] ? hi[0] - lo[0] : hi[1] - lo[1];
  const float cell = extent / static_cast<float>(kTerrainGridSide);
  g.cell = cell > kMinTerrainCell ? cell : kMinTerrainCell;
  return g;
}

void lowest_points(const float* xyz, uint32_t n, const Grid& g, float* lowest) {
  for (uint32_t c = 0; c < kTerrainCells; ++c) lowest[c] = kEmptyCell;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t c = g.cell_of(xyz + 3u * i);
    lowest[c] = xyz[3u * i + 2u] < lowest[c] ? xyz[3u * i + 2u] : lowest[c];
  }
}

// Least-squares plane through the lowest points of the cells that rise at
// most max_rise above `previous` (all occupied cells without one).
bool fit_plane(const Grid& g, const float* lowest, const Plane* previous, float max_rise, Plane* out) {
  Eigen::Matrix3f ata = Eigen::Matrix3f::Zero();
  Eigen::Vector3f atz = Eigen::Vector3f::Zero();
  uint32_t used = 0;
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    if (lowest[c] == kEmptyCell) continue;
    const float x = g.centre_x(c), y = g.centre_y(c);
    if (previous != nullptr && lowest[c] - previous->at(x, y) > max_rise) continue;
    const Eigen::Vector3f row(x, y, 1.0f);
    ata.noalias() += row * row.transpose();
    atz += row * lowest[c];
    ++used;
  }
  if (used < kMinPlaneCells) return false;
  const Eigen::LDLT<Eigen::Matrix3f> ldlt(ata);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return false;
  const Eigen::Vector3f abc = ldlt.solve(atz);
  if (!abc.allFinite()) return false;
  *out = Plane{abc[0], abc[1], abc[2]};
  return true;
}

bool fit_terrain_plane(const Grid& g, const float* lowest, Plane* plane) {
  if (!fit_plane(g, lowest, nullptr, 0.0f, plane)) return false;
  for (uint32_t round = 1; round < kTerrainFitRounds; ++round) {
    const Plane previous = *plane;
    const float rise = round <= kTerrainCoarseRounds ? kObjectCellRise : kGroundCellRise;
    if (!fit_plane(g, lowest, &previous, rise, plane)) return false;
  }
  return std::sqrt(plane->a * plane->a + plane->b * plane->b) <= std::tan(deg_to_rad(kMaxTerrainSlopeDeg));
}

// Per ground cell, the mean height above the plane of its ground points
// (those within kGroundBand of its lowest point); other cells take the mean
// of their ground neighbours', or 0. Returns the number of ground cells.
uint32_t terrain_levels(const float* xyz, uint32_t n, const Grid& g, const Plane& plane, const float* lowest,
                        float* sum, float* count, uint32_t* occupied) {
  for (uint32_t c = 0; c < kTerrainCells; ++c) sum[c] = count[c] = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    const float* p = xyz + 3u * i;
    const uint32_t c = g.cell_of(p);
    const float base = plane.at(g.centre_x(c), g.centre_y(c));
    if (lowest[c] - base > kGroundCellRise || p[2] > lowest[c] + kGroundBand) continue;
    sum[c] += p[2] - plane.at(p[0], p[1]);
    count[c] += 1.0f;
  }
  uint32_t ground = 0;
  *occupied = 0;
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    *occupied += lowest[c] != kEmptyCell ? 1u : 0u;
    if (count[c] > 0.0f) {
      sum[c] /= count[c];  // sum now holds the level
      ++ground;
    }
  }
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    if (count[c] > 0.0f) continue;
    const int32_t ci = static_cast<int32_t>(c % kTerrainGridSide),
                  cj = static_cast<int32_t>(c / kTerrainGridSide);
    float s = 0.0f, k = 0.0f;
    for (int32_t dj = -1; dj <= 1; ++dj)
      for (int32_t di = -1; di <= 1; ++di) {
        const int32_t i = ci + di, j = cj + dj, side = static_cast<int32_t>(kTerrainGridSide);
        if (i < 0 || j < 0 || i >= side || j >= side) continue;
        const uint32_t nb = static_cast<uint32_t>(j * side + i);
        if (count[nb] > 0.0f) s += sum[nb], k += 1.0f;
      }
    sum[c] = k > 0.0f ? s / k : 0.0f;
    count[c] = -1.0f;  // filled from neighbours: not a ground cell itself (keeps the fill one pass deep)
  }
  return ground;
}

}  // namespace

uint32_t remove_terrain(float* xyz, uint32_t n, float clearance, float* scratch) {
  if (n == 0 || !(clearance > 0.0f)) return 0;
  float* lowest = scratch;
  float* level = scratch + kTerrainCells;
  float* count = scratch + 2u * kTerrainCells;
  const Grid g = footprint(xyz, n);
  lowest_points(xyz, n, g, lowest);
  Plane plane;
  if (!fit_terrain_plane(g, lowest, &plane)) return 0;
  uint32_t occupied = 0;
  const uint32_t ground_cells = terrain_levels(xyz, n, g, plane, lowest, level, count, &occupied);
  if (static_cast<float>(ground_cells) < kMinGroundCellShare * static_cast<float>(occupied)) return 0;
  auto on_terrain = [&](const float* p) {
    return p[2] - plane.at(p[0], p[1]) - level[g.cell_of(p)] <= clearance;
  };
  uint32_t near = 0;
  for (uint32_t i = 0; i < n; ++i) near += on_terrain(xyz + 3u * i) ? 1u : 0u;
  if (static_cast<float>(near) < kMinGroundShare * static_cast<float>(n)) return 0;
  uint32_t kept = 0;
  for (uint32_t i = 0; i < n; ++i) {
    if (on_terrain(xyz + 3u * i)) continue;
    for (uint32_t a = 0; a < 3u; ++a) xyz[3u * kept + a] = xyz[3u * i + a];
    ++kept;
  }
  return n - kept;
}

}  // namespace spinhash
