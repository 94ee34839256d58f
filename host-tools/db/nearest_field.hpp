// Per-model nearest-feature field (the blob's kNearestField, described in
// blob_format.hpp): for every voxel of a grid around the model, the features
// nearest the voxel's centre, one per surface orientation, so verification
// finds a warped query feature's model feature in O(slots).
#pragma once
#include <cstdint>
#include <vector>

namespace spinhash {
namespace host {

struct FieldOptions {
  float cell = 0.4f;        // m, voxel edge (0: no field); +14.5 B per model feature
  float reach = 0.6f;       // m, the largest Delta_max the field answers for (the default Delta_max)
  uint32_t slots = 3;       // features per voxel: a corner shows three faces
  float split_deg = 35.0f;  // a further slot's normal differs this much from nearer ones (default eta_max)
};

struct NearestField {
  uint32_t dims[3] = {0, 0, 0};
  std::vector<uint16_t> entries;  // slots per voxel, x fastest; kNoFieldFeature pads
};

// positions: 3 floats and normals: 3 encoded int16 (encode_normal_component)
// per feature, in the model's blob order; grid_origin: the model grid's
// corner (the field starts opt.reach below it). false when the model has too
// many features for uint16 slots or the field too many voxels.
bool build_nearest_field(const float* positions, const int16_t* normals, uint32_t count,
                         const float grid_origin[3], const FieldOptions& opt, NearestField* out);

}  // namespace host
}  // namespace spinhash
