#include "lookalikes.hpp"

#include <string>

namespace spinhash::experiment {
namespace {

enum class CopyKind : uint32_t { kLonger, kShorter, kWider, kNarrower, kMirrored, kCount };

const char* kind_tag(CopyKind k) {
  switch (k) {
    case CopyKind::kLonger: return "sx+";
    case CopyKind::kShorter: return "sx-";
    case CopyKind::kWider: return "sy+";
    case CopyKind::kNarrower: return "sy-";
    default: return "m";
  }
}

// Scales about the model's origin (the models stand on z = 0, centred in x
// and y); a negative y scale mirrors, and Mesh::apply_transform keeps the
// winding outward.
Eigen::Matrix4d copy_transform(CopyKind kind, uint32_t level) {
  const double step = kLookalikeStep * level;
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  switch (kind) {
    case CopyKind::kLonger: t(0, 0) = 1.0 + step; break;
    case CopyKind::kShorter: t(0, 0) = 1.0 - step; break;
    case CopyKind::kWider: t(1, 1) = 1.0 + step; break;
    case CopyKind::kNarrower: t(1, 1) = 1.0 - step; break;
    default: t(1, 1) = -1.0; t(0, 0) = 1.0 + kLookalikeStep * (level - 1);
  }
  return t;
}

}  // namespace

std::vector<pipeline::ModelMesh> with_lookalikes(const std::vector<pipeline::ModelMesh>& originals,
                                                 uint32_t copies) {
  std::vector<pipeline::ModelMesh> out = originals;
  const uint32_t kinds = static_cast<uint32_t>(CopyKind::kCount);
  for (uint32_t k = 0; k < copies && k < kMaxLookalikesPerModel; ++k)
    for (const pipeline::ModelMesh& m : originals) {
      const CopyKind kind = static_cast<CopyKind>(k % kinds);
      const uint32_t level = k / kinds + 1;
      pipeline::ModelMesh copy{m.name + "~" + kind_tag(kind) + std::to_string(level), m.mesh,
                               m.vehicle_class};
      copy.mesh.name = copy.name;
      copy.mesh.apply_transform(copy_transform(kind, level));
      out.push_back(std::move(copy));
    }
  return out;
}

}  // namespace spinhash::experiment
