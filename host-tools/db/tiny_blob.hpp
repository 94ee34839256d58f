// Small, fully consistent blob content for tests (no meshes, no core feature
// extraction): random but valid positions, unit normals, spins, per-model
// grids and an LSH index whose buckets agree with the spins.
#pragma once
#include <cstdint>

#include "blob/blob_content.hpp"

namespace spinhash {
namespace host {

// Same arguments -> same content on every platform. models in [1, kMaxModels],
// features_per_model >= 1 (otherwise the writer refuses the result).
BlobContent make_tiny_blob_content(uint32_t models, uint32_t features_per_model, uint64_t seed);

}  // namespace host
}  // namespace spinhash
