// The poses the final lending (recognize/final_lending.cpp) gives a sibling
// of another length (match/refine_pose.hpp, end_aligned_pose): the first
// model's pose with the two boxes' rear ends, or front ends, coinciding,
// each also turned end to end. The procedural fleet's vehicles are centred
// on their boxes, so the pose as it is puts a sibling a metre longer half a
// metre off at either end, where no refinement step reaches.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "match/refine_pose.hpp"
#include "recognize/box_distance.hpp"
#include "spinhash/blob_format.hpp"

using namespace spinhash;

namespace {

const float kMinEndShift = RefineParams{}.lend_min_end_shift;  // m: 0.05

constexpr float kYaw = 0.7f;
constexpr float kTolerance = 1e-4f;  // m

blob::ModelRecord centred_box(float length) {
  blob::ModelRecord r{};
  r.bbox_min[0] = -0.5f * length, r.bbox_max[0] = 0.5f * length;
  r.bbox_min[1] = -1.2f, r.bbox_max[1] = 1.2f;
  r.bbox_min[2] = 0.0f, r.bbox_max[2] = 3.0f;
  return r;
}

RigidPose yawed_pose() {
  RigidPose p;
  p.rotation = Eigen::AngleAxisf(kYaw, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  p.translation = Eigen::Vector3f(12.0f, -4.0f, 0.3f);
  return p;
}

Eigen::Vector3f apply(const RigidPose& p, const Eigen::Vector3f& x) { return p.rotation * x + p.translation; }

}  // namespace

TEST_CASE("end-aligned poses put a longer sibling's rear, then its front, on the first model's") {
  const blob::ModelRecord first = centred_box(11.0f), sibling = centred_box(12.0f);
  const RigidPose pose = yawed_pose();
  RigidPose out[kEndAlignedPoses];
  for (uint32_t i = 0; i < kEndAlignedPoses; ++i)
    REQUIRE(end_aligned_pose(pose, first, sibling, i, &out[i], kMinEndShift));
  const Eigen::Vector3f side(0.0f, 1.2f, 1.0f);  // a point on the left side, mid-height
  const Eigen::Vector3f first_rear = apply(pose, side + Eigen::Vector3f(first.bbox_min[0], 0, 0));
  const Eigen::Vector3f first_front = apply(pose, side + Eigen::Vector3f(first.bbox_max[0], 0, 0));
  const Eigen::Vector3f sib_rear = side + Eigen::Vector3f(sibling.bbox_min[0], 0, 0);
  const Eigen::Vector3f sib_front = side + Eigen::Vector3f(sibling.bbox_max[0], 0, 0);
  // Rear ends together, then front ends together, same heading.
  CHECK((apply(out[0], sib_rear) - first_rear).norm() < kTolerance);
  CHECK((apply(out[2], sib_front) - first_front).norm() < kTolerance);
  CHECK((out[0].rotation - pose.rotation).norm() < kTolerance);
  // Turned: the sibling's front where the first's rear was (its left side on
  // the first's right), for a first model fitted the wrong way round.
  const Eigen::Vector3f mirrored(0.0f, -2.4f, 0.0f);  // left side to right side
  CHECK((apply(out[1], sib_front) - apply(pose, side + mirrored + Eigen::Vector3f(first.bbox_min[0], 0, 0)))
            .norm() < kTolerance);
  CHECK((apply(out[3], sib_rear) - apply(pose, side + mirrored + Eigen::Vector3f(first.bbox_max[0], 0, 0)))
            .norm() < kTolerance);
  CHECK((out[1].rotation.col(0) + pose.rotation.col(0)).norm() < kTolerance);
}

TEST_CASE("a sibling of the same length gets the pose as it is and the turned ones, not pose 0 twice") {
  const blob::ModelRecord first = centred_box(4.4f), twin = centred_box(4.42f);  // within lend_min_end_shift
  const RigidPose pose = yawed_pose();
  RigidPose out;
  REQUIRE(
      end_aligned_pose(pose, first, twin, 0, &out, kMinEndShift));  // rear ends 0.01 m apart: nearly as it is
  CHECK((out.translation - pose.translation).norm() < 0.011f);
  CHECK((out.rotation - pose.rotation).norm() < kTolerance);
  CHECK(!end_aligned_pose(pose, first, twin, 2, &out, kMinEndShift));  // front ends: pose 0 once more
  // A sibling of the first's length in a frame 0.3 m along: one shifted pose.
  blob::ModelRecord shifted = centred_box(4.4f);
  shifted.bbox_min[0] += 0.3f, shifted.bbox_max[0] += 0.3f;
  REQUIRE(end_aligned_pose(pose, first, shifted, 0, &out, kMinEndShift));
  CHECK((out.translation - (pose.translation - 0.3f * pose.rotation.col(0))).norm() < kTolerance);
  CHECK(!end_aligned_pose(pose, first, shifted, 2, &out, kMinEndShift));
  const RigidPose turned = turned_end_to_end(pose, twin);
  // Each shift is 0.01 m, within lend_min_end_shift: the turned poses are nearly the plain turn.
  for (uint32_t i : {1u, 3u}) {
    REQUIRE(end_aligned_pose(pose, first, twin, i, &out, kMinEndShift));
    CHECK((out.translation - turned.translation).norm() < 0.011f);
    CHECK((out.rotation - turned.rotation).norm() < kTolerance);
  }
}

TEST_CASE("the look-alike box test stops early and still agrees with the box distance") {
  const blob::ModelRecord a = centred_box(4.5f);
  for (float length : {4.5f, 4.6f, 4.8f, 5.5f, 9.0f}) {
    blob::ModelRecord b = centred_box(length);
    b.bbox_max[2] = 3.05f;  // a little taller too: every axis counts
    const float d = box_distance(a, b);
    CAPTURE(length);
    for (float limit : {0.0f, 0.5f * d, d, d + 0.01f, 0.6f, 10.0f})
      CHECK(boxes_within(a, b, limit) == (d <= limit));
  }
  blob::ModelRecord broken = centred_box(4.5f);
  broken.bbox_max[2] = std::nanf("");
  CHECK_FALSE(boxes_within(a, broken, 10.0f));  // as box_distance's comparison
}
