// Per-model nearest-feature field (the blob's kNearestField, described in
// blob_format.hpp): for every voxel of a grid around the model, the features
// nearest the voxel's centre, one per surface orientation, so verification
// finds a warped query feature's model feature in O(slots).
#pragma once
#include <cstdint>
#include <vector>

#include "blob/blob_content.hpp"

namespace spinhash {
namespace host {

struct FieldOptions {
  float cell = 0.4f;        // m, voxel edge (0: no field); +14.5 B per model feature
  float reach = 0.6f;       // m, the largest Delta_max the field answers for (the default Delta_max)
  uint32_t slots = 3;       // features per voxel: a corner shows three faces
  float split_deg = 35.0f;  // a further slot's normal differs this much from nearer ones (default eta_max)
};

// Builds the field of `record`'s model, whose features are already in
// `content` (blob order, encoded normals), over its grid origin and bounding
// box, and appends it: the record gets its field_dims and field_base. With
// opt.cell == 0 the model gets no field. false, with nothing changed, when
// the model has too many features for uint16 slots, the field too many
// voxels, or the section would outgrow 32-bit offsets.
bool append_nearest_field(const FieldOptions& opt, blob::ModelRecord* record, BlobContent* content);

}  // namespace host
}  // namespace spinhash
