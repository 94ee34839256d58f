// Point sets with known geometry for the core tests.
#pragma once
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

}  // namespace test
}  // namespace spinhash
