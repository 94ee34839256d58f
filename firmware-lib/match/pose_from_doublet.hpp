// Rigid pose from two oriented-point correspondences: least squares (Kabsch,
// fixed-size 3x3 SVD) over the two points and the two normal tips.
#pragma once
#include "match/oriented_point.hpp"

namespace spinhash {

// Pose taking model points (m1, m2) onto query points (q1, q2); false when
// degenerate. The normal tips sit `normal_lever` m from their points
// (DrawsParams::normal_lever), so a normal error of e radians weighs like a
// position error of e * normal_lever metres.
bool pose_from_doublet(const OrientedPoint& q1, const OrientedPoint& q2, const OrientedPoint& m1,
                       const OrientedPoint& m2, RigidPose* out, float normal_lever);

}  // namespace spinhash
