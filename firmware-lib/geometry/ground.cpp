#include "geometry/ground.hpp"

#include <cmath>

namespace spinhash {
namespace {

bool ground_cell(const TerrainGrid& g, uint32_t c) { return !std::isnan(g.value[c]) && !g.off_ground[c]; }

// True when the ground cells join like terrain: few neighbour pairs (right
// and up) step by more than kMaxGroundStepSlope per m plus kMaxGroundStepExtra.
bool ground_is_terrain(const TerrainGrid& g) {
  const float max_step = kMaxGroundStepSlope * g.cell + kMaxGroundStepExtra;
  uint32_t pairs = 0, steep = 0;
  for (uint32_t y = 0; y < g.ny; ++y)
    for (uint32_t x = 0; x < g.nx; ++x) {
      const uint32_t c = y * g.nx + x;
      if (!ground_cell(g, c)) continue;
      const uint32_t next[2] = {x + 1u < g.nx ? c + 1u : c, y + 1u < g.ny ? c + g.nx : c};
      for (uint32_t d : next) {
        if (d == c || !ground_cell(g, d)) continue;
        ++pairs;
        steep += std::fabs(g.value[d] - g.value[c]) > max_step ? 1u : 0u;
      }
    }
  return static_cast<float>(steep) <= kMaxSteepGroundShare * static_cast<float>(pairs);
}

}  // namespace

uint32_t remove_ground(float* xyz, uint32_t n, float clearance, TerrainGrid& grid, float* height, uint8_t* ground) {
  if (n == 0 || !(clearance > 0.0f)) return 0;
  float lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {xyz[0], xyz[1], xyz[2]};
  for (uint32_t i = 1; i < n; ++i)
    for (uint32_t a = 0; a < 3u; ++a) {
      const float v = xyz[3u * i + a];
      lo[a] = v < lo[a] ? v : lo[a];
      hi[a] = v > hi[a] ? v : hi[a];
    }
  if (!(hi[2] - lo[2] > clearance)) return 0;  // all within one slab: nothing stands on a ground
  // Cells of kQueryTerrainCell, or coarser so that the query fits the grid.
  const float side = std::sqrt(static_cast<float>(grid.max_cells)) - 2.0f;
  const float span = hi[0] - lo[0] > hi[1] - lo[1] ? hi[0] - lo[0] : hi[1] - lo[1];
  TerrainParams p;
  p.cell = span / side > kQueryTerrainCell ? span / side : kQueryTerrainCell;
  p.max_window = p.max_window > p.cell ? p.max_window : p.cell;
  p.ground_height = clearance;
  if (classify_terrain(xyz, n, p, grid, height, ground, nullptr) != Status::kOk) return 0;  // keep all
  uint32_t on_ground = 0;
  for (uint32_t i = 0; i < n; ++i) on_ground += ground[i];
  if (static_cast<float>(on_ground) < kMinGroundShare * static_cast<float>(n)) return 0;
  if (!ground_is_terrain(grid)) return 0;
  // Cells: 0 empty, 1 ground only, 2 anything standing (the opening buffer is free now).
  const uint32_t cells = grid.nx * grid.ny;
  for (uint32_t c = 0; c < cells; ++c) grid.scratch[c] = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    float& mark = grid.scratch[terrain_cell_of(grid, xyz[3u * i], xyz[3u * i + 1u])];
    mark = ground[i] ? (mark > 1.0f ? mark : 1.0f) : 2.0f;
  }
  uint32_t occupied = 0, open = 0;
  for (uint32_t c = 0; c < cells; ++c) {
    occupied += grid.scratch[c] > 0.0f ? 1u : 0u;
    open += grid.scratch[c] == 1.0f ? 1u : 0u;
  }
  if (static_cast<float>(open) < kMinOpenGroundShare * static_cast<float>(occupied)) return 0;
  uint32_t kept = 0;
  for (uint32_t i = 0; i < n; ++i) {
    if (ground[i]) continue;
    for (uint32_t a = 0; a < 3u; ++a) xyz[3u * kept + a] = xyz[3u * i + a];
    ++kept;
  }
  return n - kept;
}

}  // namespace spinhash
