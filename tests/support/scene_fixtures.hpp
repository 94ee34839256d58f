// Synthetic airborne tiles for the terrain, segmentation and scene tests:
// a sloped terrain with a bump and a curb, and objects resting on it.
#pragma once
#include <cstdint>
#include <vector>

namespace spinhash {
namespace test {

struct TerrainShape {
  double slope_deg = 0.0;    // rising along +x
  double bump_height = 0.4;  // m: Gaussian bump at (bump_x, bump_y)
  double bump_sigma = 1.5;   // m
  double bump_x = -6.0, bump_y = 6.0;
  double curb_height = 0.15;  // m: step up for y > curb_y
  double curb_y = -7.0;
  double z0 = 0.0;
};

double terrain_z(const TerrainShape& t, double x, double y);

// Tile under construction: xyz and, per point, whether it is ground.
struct Tile {
  std::vector<double> xyz;
  std::vector<uint8_t> ground;
  std::vector<int> object;  // -1 ground, else the index of the add_* call that made it
  int objects = 0;
  struct Footprint {
    double cx, cy, yaw, half_x, half_y;
  };
  std::vector<Footprint> roofs;  // footprints of boxes and models: no ground seen under them
  void add(double x, double y, double z, bool is_ground, int obj);
};

// Drops the ground points under every box and model (the sensor sees roofs, not
// what lies under them); call once the tile is complete.
void remove_occluded_ground(Tile& tile);

// Ground points on a square grid over [-half, half]^2 with deterministic noise (m).
void add_terrain(Tile& tile, const TerrainShape& t, double half, double spacing, double noise, uint64_t seed);
// The same over the rectangle [x0, x1] x [y0, y1] (a strip of a flight line).
void add_terrain_rect(Tile& tile, const TerrainShape& t, double x0, double x1, double y0, double y1,
                      double spacing, double noise, uint64_t seed);
// Top and sides of an axis-aligned box (footprint sx x sy, sz tall, bottom `clearance`
// above the terrain), rotated by yaw about z, resting on the terrain at (cx, cy):
// each point raised by the terrain under it. Returns the object index.
int add_box(Tile& tile, const TerrainShape& t, double cx, double cy, double yaw, double sx, double sy,
            double sz, double clearance, double spacing);
// A tree: a trunk (0.3 m square) and a crown (points on a sphere of radius r at height hc).
int add_tree(Tile& tile, const TerrainShape& t, double cx, double cy, double trunk_x, double trunk_y,
             double hc, double r, double spacing);
// Model points (model frame, z up, wheels at z ~ 0) placed rigidly: pitched to the slope
// along x, yawed, and set on the terrain at (cx, cy); points below min_z (the underside) left out.
int add_model(Tile& tile, const TerrainShape& t, const std::vector<double>& model, double cx, double cy,
              double yaw, double min_z);

// The tile's points in scan order: sorted along `axis` (0 x, 1 y), ties kept
// in the order they were added, each shifted by `offset` (georeferencing).
std::vector<double> in_scan_order(const Tile& tile, int axis, const double offset[3] = nullptr);

// The terrain tests' 24 x 24 m tile on a slope of `slope_deg` (the default
// bump and curb): terrain at 0.2 m spacing with 3 cm noise, a car-sized
// box (4.5 x 1.8 x 1.2 m, 0.3 m clearance), a building (10 x 7 x 5 m) and a
// low crate (1 x 1 x 0.6 m), no ground under them.
Tile terrain_sample_tile(double slope_deg);

}  // namespace test
}  // namespace spinhash
