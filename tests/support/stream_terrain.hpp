// The terrain of a cloud as the scene stream makes it, for the terrain and
// segmentation tests: the points in the stream's buffer (PointRing, a frame
// with s = x, t = y from (0, 0)), each cell's sums (TerrainCells::sum),
// the parts over the cells that hold points (TerrainCells::fill), the
// filter (terrain_finish) and every point's height (terrain_heights).
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/terrain.hpp"
#include "spinhash/status.hpp"
#include "support/scene_fixtures.hpp"

namespace spinhash {
namespace test {

struct StreamTerrain {
  Status status = Status::kNotOpen;
  std::vector<float> local;  // x y z per point, as the stream's windows see them (from the lattice)
  std::vector<float> height;
  std::vector<uint8_t> ground;
  uint32_t points_ground = 0;
  uint32_t cells = 0;  // in the parts, together
  uint32_t parts = 0;
  uint32_t windows = 0;                  // PMF windows run
  uint32_t noise_cells = 0;              // cells whose lowest was left out as low noise
  std::vector<float> surface_at_points;  // the terrain under each point
};

// xyz: n points (x y z) within a few kilometres of (0, 0). max_cells: the
// parts' grid cells. kOk, kTileTooLarge (more cells needed), kInvalidArgument
// (parameters out of range).
StreamTerrain stream_terrain(const std::vector<double>& xyz, const TerrainParams& params,
                             uint32_t max_cells = 1u << 17);

// Ground recall and precision of `c` over the tile's points (the first of
// c's: points added after the tile's are not scored). Truth: ground, or
// within ground_height of the true terrain `t` (the foot of a wall is
// ground by definition).
struct GroundScore {
  uint32_t tp = 0, fp = 0, fn = 0;
  double recall() const { return static_cast<double>(tp) / (tp + fn); }
  double precision() const { return static_cast<double>(tp) / (tp + fp); }
};
GroundScore ground_score(const Tile& tile, const TerrainShape& t, const StreamTerrain& c);

}  // namespace test
}  // namespace spinhash
