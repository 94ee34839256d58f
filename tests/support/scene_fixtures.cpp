#include "support/scene_fixtures.hpp"

#include <algorithm>
#include <cmath>

#include "support/geometry_fixtures.hpp"

namespace spinhash {
namespace test {

double terrain_z(const TerrainShape& t, double x, double y) {
  const double kPi = 3.14159265358979;
  const double dx = x - t.bump_x, dy = y - t.bump_y;
  return t.z0 + std::tan(t.slope_deg * kPi / 180.0) * x +
         t.bump_height * std::exp(-(dx * dx + dy * dy) / (2.0 * t.bump_sigma * t.bump_sigma)) +
         (y > t.curb_y ? t.curb_height : 0.0);
}

void Tile::add(double x, double y, double z, bool is_ground, int obj) {
  xyz.push_back(x);
  xyz.push_back(y);
  xyz.push_back(z);
  ground.push_back(is_ground ? 1 : 0);
  object.push_back(obj);
}

void remove_occluded_ground(Tile& tile) {
  Tile kept;
  kept.objects = tile.objects;
  kept.roofs = tile.roofs;
  for (size_t i = 0; i < tile.ground.size(); ++i) {
    const double x = tile.xyz[3 * i], y = tile.xyz[3 * i + 1];
    bool under = false;
    for (const Tile::Footprint& f : tile.roofs) {
      const double dx = x - f.cx, dy = y - f.cy;
      const double u = std::cos(f.yaw) * dx + std::sin(f.yaw) * dy,
                   v = -std::sin(f.yaw) * dx + std::cos(f.yaw) * dy;
      under = under || (std::fabs(u) < f.half_x && std::fabs(v) < f.half_y);
    }
    if (tile.ground[i] && under) continue;
    kept.add(x, y, tile.xyz[3 * i + 2], tile.ground[i] != 0, tile.object[i]);
  }
  tile = kept;
}

void add_terrain(Tile& tile, const TerrainShape& t, double half, double spacing, double noise,
                 uint64_t seed) {
  add_terrain_rect(tile, t, -half, half, -half, half, spacing, noise, seed);
}

void add_terrain_rect(Tile& tile, const TerrainShape& t, double x0, double x1, double y0, double y1,
                      double spacing, double noise, uint64_t seed) {
  uint64_t state = seed * 6364136223846793005ull + 1442695040888963407ull;
  auto uniform = [&state]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0);
  };
  const int nx = static_cast<int>((x1 - x0) / spacing), ny = static_cast<int>((y1 - y0) / spacing);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = x0 + i * spacing + (uniform() - 0.5) * spacing * 0.5;
      const double y = y0 + j * spacing + (uniform() - 0.5) * spacing * 0.5;
      const double n = noise * (uniform() + uniform() + uniform() - 1.5) * 2.0;
      tile.add(x, y, terrain_z(t, x, y) + n, true, -1);
    }
}

int add_box(Tile& tile, const TerrainShape& t, double cx, double cy, double yaw, double sx, double sy,
            double sz, double clearance, double spacing) {
  const int id = tile.objects++;
  tile.roofs.push_back(Tile::Footprint{cx, cy, yaw, 0.5 * sx, 0.5 * sy});
  std::vector<float> s = box_surface(static_cast<float>(sx), static_cast<float>(sy), static_cast<float>(sz),
                                     static_cast<float>(spacing));
  const double c = std::cos(yaw), sn = std::sin(yaw);
  for (size_t i = 0; i < s.size(); i += 3) {
    const double z = s[i + 2] + 0.5 * sz;  // box_surface is centred
    if (z < 1e-3) continue;                // the underside is not seen from the air
    const double x = cx + c * s[i] - sn * s[i + 1], y = cy + sn * s[i] + c * s[i + 1];
    tile.add(x, y, terrain_z(t, x, y) + clearance + z, false, id);
  }
  return id;
}

int add_tree(Tile& tile, const TerrainShape& t, double cx, double cy, double trunk_x, double trunk_y,
             double hc, double r, double spacing) {
  const int id = tile.objects++;
  const double base = terrain_z(t, trunk_x, trunk_y);
  for (double z = 0.3; z < hc - r; z += spacing)
    for (int k = 0; k < 4; ++k)
      tile.add(trunk_x + 0.15 * (k & 1 ? 1 : -1), trunk_y + 0.15 * (k & 2 ? 1 : -1), base + z, false, id);
  const uint32_t n = static_cast<uint32_t>(4.0 * 3.14159 * r * r / (spacing * spacing));
  std::vector<float> sphere = fibonacci_sphere(n, static_cast<float>(r), 0.0f, 0.0f, 0.0f);
  for (size_t i = 0; i < sphere.size(); i += 3)
    tile.add(cx + sphere[i], cy + sphere[i + 1], base + hc + sphere[i + 2], false, id);
  return id;
}

int add_model(Tile& tile, const TerrainShape& t, const std::vector<double>& model, double cx, double cy,
              double yaw, double min_z) {
  const int id = tile.objects++;
  const double kPi = 3.14159265358979;
  const double a = std::atan(std::tan(t.slope_deg * kPi / 180.0));
  const double ca = std::cos(a), sa = std::sin(a), cy_ = std::cos(yaw), sy_ = std::sin(yaw);
  const double base = terrain_z(t, cx, cy);
  double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
  for (size_t i = 0; i < model.size(); i += 3)
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::fmin(lo[a], model[i + a]);
      hi[a] = std::fmax(hi[a], model[i + a]);
    }
  // Footprint on the ground (the pitch shortens it by cos(a); centred models assumed).
  tile.roofs.push_back(Tile::Footprint{cx, cy, yaw, 0.5 * (hi[0] - lo[0]) * ca, 0.5 * (hi[1] - lo[1])});
  for (size_t i = 0; i < model.size(); i += 3) {
    if (model[i + 2] < min_z) continue;
    // yaw about z, then pitch so that the plane z = 0 follows the slope along x
    const double x1 = cy_ * model[i] - sy_ * model[i + 1], y1 = sy_ * model[i] + cy_ * model[i + 1];
    const double z1 = model[i + 2];
    tile.add(cx + ca * x1 - sa * z1, cy + y1, base + sa * x1 + ca * z1, false, id);
  }
  return id;
}

std::vector<double> in_scan_order(const Tile& tile, int axis, const double offset[3]) {
  const size_t n = tile.xyz.size() / 3;
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return tile.xyz[3 * a + axis] < tile.xyz[3 * b + axis]; });
  std::vector<double> xyz;
  xyz.reserve(3 * n);
  for (size_t i : order)
    for (int k = 0; k < 3; ++k) {
      const double v = tile.xyz[3 * i + k];
      xyz.push_back(offset != nullptr ? v + offset[k] : v);
    }
  return xyz;
}

Tile terrain_sample_tile(double slope_deg) {
  TerrainShape t;
  t.slope_deg = slope_deg;
  Tile tile;
  add_terrain(tile, t, 12.0, 0.2, 0.03, 7);
  add_box(tile, t, 2.0, -2.0, 0.4, 4.5, 1.8, 1.2, 0.3, 0.1);
  add_box(tile, t, 5.0, 6.5, 0.0, 10.0, 7.0, 5.0, 0.0, 0.2);
  add_box(tile, t, -5.0, -4.0, 0.0, 1.0, 1.0, 0.6, 0.0, 0.1);
  remove_occluded_ground(tile);
  return tile;
}

}  // namespace test
}  // namespace spinhash
