#include "support/stream_terrain.hpp"

#include <cmath>

#include "scene/point_ring.hpp"
#include "scene/terrain_cells.hpp"

namespace spinhash {
namespace test {

StreamTerrain stream_terrain(const std::vector<double>& xyz, const TerrainParams& params,
                             uint32_t max_cells) {
  StreamTerrain r;
  const uint32_t n = static_cast<uint32_t>(xyz.size() / 3);
  if (!terrain_params_valid(params)) {
    r.status = Status::kInvalidArgument;
    return r;
  }
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (uint32_t i = 0; i < n; ++i)
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::fmin(lo[a], xyz[3 * i + a]);
      hi[a] = std::fmax(hi[a], xyz[3 * i + a]);
    }
  const double cell = params.cell;
  const double s0 = std::floor(lo[0] / cell) * cell - cell, s1 = std::floor(hi[0] / cell) * cell + 2.0 * cell;
  const double t0 = std::floor(lo[1] / cell) * cell - cell, t1 = std::floor(hi[1] / cell) * cell + 2.0 * cell;
  PointRing ring;
  TerrainCells cells;
  TerrainParts parts;
  Arena counter;
  ring.carve(counter, n);
  cells.carve(counter, cell, s1 - s0, t1 - t0);
  parts.carve(counter, max_cells);
  std::vector<uint8_t> bytes(counter.used() + 64);
  Arena arena(bytes.data(), bytes.size());
  ring.carve(arena, n);
  cells.carve(arena, cell, s1 - s0, t1 - t0);
  parts.carve(arena, max_cells);
  cells.low_band = params.low_band;
  cells.noise_gap = params.noise_gap;
  cells.start(t0);
  for (uint32_t i = 0; i < n; ++i) ring.push(&xyz[3 * i]);
  cells.sum(ring, s0, s1);
  FrameRect rect;
  rect.s0 = s0;
  rect.s1 = s1;
  rect.t0 = t0;
  rect.t1 = t1;
  r.status = cells.fill(rect, rect, 0.0, 0.0, terrain_reach_cells(params), parts);
  if (r.status != Status::kOk) return r;
  r.windows = terrain_finish(parts, params, &r.noise_cells);
  r.cells = parts.cells;
  r.parts = parts.count;
  for (uint32_t i = 0; i < n; ++i) {
    double p[3];
    ring.get(i, p);
    for (int a = 0; a < 3; ++a) r.local.push_back(static_cast<float>(p[a]));
  }
  r.height.resize(n);
  r.ground.resize(n);
  r.points_ground =
      terrain_heights(parts, r.local.data(), n, params.ground_height, r.height.data(), r.ground.data());
  for (uint32_t i = 0; i < n; ++i)
    r.surface_at_points.push_back(terrain_height_at(parts, r.local[3 * i], r.local[3 * i + 1]));
  return r;
}

GroundScore ground_score(const Tile& tile, const TerrainShape& t, const StreamTerrain& c) {
  const float limit = TerrainParams{}.ground_height;
  GroundScore s;
  for (size_t i = 0; i < tile.ground.size(); ++i) {
    const double* p = &tile.xyz[3 * i];
    const bool truth = tile.ground[i] || p[2] - terrain_z(t, p[0], p[1]) <= limit;
    s.tp += truth && c.ground[i];
    s.fp += !truth && c.ground[i];
    s.fn += truth && !c.ground[i];
  }
  return s;
}

}  // namespace test
}  // namespace spinhash
