// The database without one of its models, derived from the full content:
// the same quantisation, LSH bits, grids and fields, the model's features
// and entries taken out and the indices after them renumbered. What a
// vehicle of that model, unknown to the database, meets (the calibration's
// leave-one-model-out runs), without extracting any model's features again.
#pragma once
#include <cstdint>

#include "blob/blob_content.hpp"

namespace spinhash {
namespace host {

// `full` with model `model` removed; false (and *out untouched) when the
// content holds fewer than two models or `model` is out of range. The
// result's calibration is the priors (a derived database is not calibrated).
bool without_model(const BlobContent& full, uint32_t model, BlobContent* out);

}  // namespace host
}  // namespace spinhash
