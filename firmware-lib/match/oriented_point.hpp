// An oriented point (position, unit normal): what a feature contributes to geometry.
#pragma once
#include <Eigen/Core>

namespace spinhash {

struct OrientedPoint {
  Eigen::Vector3f p;
  Eigen::Vector3f n;
};

// x = R * m + t, model frame -> query frame.
struct RigidPose {
  Eigen::Matrix3f rotation;
  Eigen::Vector3f translation;
};

}  // namespace spinhash
