#include "support/geometry_fixtures.hpp"

#include <cmath>

namespace spinhash {
namespace test {

std::vector<float> plane_grid(float half, float spacing) {
  std::vector<float> pts;
  int n = static_cast<int>(std::lround(half / spacing));
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      pts.push_back(static_cast<float>(i) * spacing);
      pts.push_back(static_cast<float>(j) * spacing);
      pts.push_back(0.0f);
    }
  return pts;
}

std::vector<float> fibonacci_sphere(uint32_t n, float radius, float cx, float cy, float cz) {
  std::vector<float> pts;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (uint32_t i = 0; i < n; ++i) {
    double z = 1.0 - (2.0 * i + 1.0) / n;
    double r = std::sqrt(1.0 - z * z);
    double phi = golden * i;
    pts.push_back(cx + radius * static_cast<float>(r * std::cos(phi)));
    pts.push_back(cy + radius * static_cast<float>(r * std::sin(phi)));
    pts.push_back(cz + radius * static_cast<float>(z));
  }
  return pts;
}

std::vector<float> sphere_normals(const std::vector<float>& pts, float cx, float cy, float cz) {
  std::vector<float> n(pts.size());
  for (size_t i = 0; i < pts.size(); i += 3) {
    float d[3] = {pts[i] - cx, pts[i + 1] - cy, pts[i + 2] - cz};
    float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int a = 0; a < 3; ++a) n[i + a] = d[a] / len;
  }
  return n;
}

std::vector<float> box_surface(float sx, float sy, float sz, float spacing) {
  std::vector<float> pts;
  const float size[3] = {sx, sy, sz};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      int nu = static_cast<int>(size[u] / spacing), nv = static_cast<int>(size[v] / spacing);
      for (int i = 0; i <= nu; ++i)
        for (int j = 0; j <= nv; ++j) {
          float p[3];
          p[axis] = side == 0 ? -size[axis] / 2 : size[axis] / 2;
          p[u] = -size[u] / 2 + static_cast<float>(i) * size[u] / static_cast<float>(nu);
          p[v] = -size[v] / 2 + static_cast<float>(j) * size[v] / static_cast<float>(nv);
          pts.insert(pts.end(), p, p + 3);
        }
    }
  return pts;
}

}  // namespace test
}  // namespace spinhash
