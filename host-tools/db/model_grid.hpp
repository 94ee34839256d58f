// Per-model feature grid (the blob's kGridOffsets): features sorted by cell
// so the likelihood finds a query feature's nearest model feature in the
// 27 cells around it instead of scanning the model.
#pragma once
#include <cstdint>
#include <vector>

namespace spinhash {
namespace host {

struct ModelGrid {
  float origin[3] = {0, 0, 0};
  uint32_t dims[3] = {1, 1, 1};
  std::vector<uint32_t> order;    // feature indices (within the model) sorted by cell
  std::vector<uint32_t> offsets;  // cells + 1, into order
};

// positions: 3 per feature, model frame.
ModelGrid build_model_grid(const std::vector<float>& positions, uint32_t count, float cell);

}  // namespace host
}  // namespace spinhash
