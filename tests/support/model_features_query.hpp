// A query made of one database model's own features moved by a known pose:
// every query feature has an exact counterpart in the model, for tests of
// the likelihood, the refinement and the searches.
#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "match/likelihood.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace test {

struct ModelFeatureQuery {
  std::vector<float> positions, normals;
  std::vector<uint8_t> spins;
  QueryFeatures view;  // points into the vectors above
};

inline RigidPose make_pose(float yaw, float tilt, const Eigen::Vector3f& t) {
  RigidPose p;
  p.rotation =
      (Eigen::AngleAxisf(yaw, Eigen::Vector3f::UnitZ()) * Eigen::AngleAxisf(tilt, Eigen::Vector3f::UnitX()))
          .toRotationMatrix();
  p.translation = t;
  return p;
}

// Model `model`'s features under `pose` (x_query = R x_model + t), all scored.
inline void model_feature_query(const Database& db, uint32_t model, const RigidPose& pose,
                                ModelFeatureQuery* q) {
  const blob::ModelRecord& rec = db.model(model);
  const uint32_t dims = db.spin_dims();
  for (uint32_t f = rec.first_feature; f < rec.first_feature + rec.feature_count; ++f) {
    const Eigen::Vector3f p(db.positions()[3u * f], db.positions()[3u * f + 1u], db.positions()[3u * f + 2u]);
    const int16_t* n16 = db.normals() + 3u * f;
    const Eigen::Vector3f n =
        Eigen::Vector3f(decode_normal_component(n16[0]), decode_normal_component(n16[1]),
                        decode_normal_component(n16[2]))
            .normalized();
    const Eigen::Vector3f x = pose.rotation * p + pose.translation, m = pose.rotation * n;
    q->positions.insert(q->positions.end(), {x.x(), x.y(), x.z()});
    q->normals.insert(q->normals.end(), {m.x(), m.y(), m.z()});
    q->spins.insert(q->spins.end(), db.spin(f), db.spin(f) + dims);
  }
  q->view.positions = q->positions.data();
  q->view.normals = q->normals.data();
  q->view.spins = q->spins.data();
  q->view.count = rec.feature_count;
  q->view.dims = dims;
  q->view.verify_count = rec.feature_count;
}

}  // namespace test
}  // namespace spinhash
