// Point sets with known geometry for the core tests.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace spinhash {
namespace test {

// Square grid on z = 0 with the given spacing, covering [-half, half]^2.
std::vector<float> plane_grid(float half, float spacing);
// n points spread evenly over a sphere (Fibonacci lattice): uniform in area.
std::vector<float> fibonacci_sphere(uint32_t n, float radius, float cx, float cy, float cz);
// Outward unit normals of points on a sphere centred at c.
std::vector<float> sphere_normals(const std::vector<float>& pts, float cx, float cy, float cz);
// Points sampled on the surface of an axis-aligned box (all six faces), spacing apart.
std::vector<float> box_surface(float sx, float sy, float sz, float spacing);

// The points (xyz triples) that keep(x, y, z) accepts, in their order.
template <typename T, typename Keep>
std::vector<T> filtered(const std::vector<T>& p, Keep keep) {
  std::vector<T> out;
  for (size_t i = 0; i + 2 < p.size(); i += 3)
    if (keep(p[i], p[i + 1], p[i + 2]))
      out.insert(out.end(), p.begin() + static_cast<long>(i), p.begin() + static_cast<long>(i) + 3);
  return out;
}

}  // namespace test
}  // namespace spinhash
