#include "db/model_grid.hpp"

#include <algorithm>
#include <cmath>

namespace spinhash {
namespace host {

ModelGrid build_model_grid(const std::vector<float>& positions, uint32_t count, float cell) {
  ModelGrid g;
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (uint32_t i = 0; i < count; ++i)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], positions[3u * i + a]);
      hi[a] = std::max(hi[a], positions[3u * i + a]);
    }
  for (int a = 0; a < 3; ++a) {
    g.origin[a] = lo[a];
    g.dims[a] = static_cast<uint32_t>(std::floor((hi[a] - lo[a]) / cell)) + 1u;
  }
  auto cell_of = [&](uint32_t i) {
    uint32_t c[3];
    for (int a = 0; a < 3; ++a) {
      float f = std::floor((positions[3u * i + a] - g.origin[a]) / cell);
      c[a] = std::min(static_cast<uint32_t>(std::max(f, 0.0f)), g.dims[a] - 1u);
    }
    return c[0] + g.dims[0] * (c[1] + g.dims[1] * c[2]);
  };
  const uint32_t cells = g.dims[0] * g.dims[1] * g.dims[2];
  g.offsets.assign(cells + 1u, 0u);
  std::vector<uint32_t> cell_index(count);
  for (uint32_t i = 0; i < count; ++i) ++g.offsets[(cell_index[i] = cell_of(i)) + 1u];
  for (uint32_t c = 0; c < cells; ++c) g.offsets[c + 1u] += g.offsets[c];
  g.order.resize(count);
  std::vector<uint32_t> cursor(g.offsets.begin(), g.offsets.end() - 1);
  for (uint32_t i = 0; i < count; ++i) g.order[cursor[cell_index[i]]++] = i;
  return g;
}

}  // namespace host
}  // namespace spinhash
