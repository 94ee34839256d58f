// Doublet cascade (Figure 5 + handedness) and the pose from two doublets.
#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include "match/doublet.hpp"
#include "match/pose_from_doublet.hpp"
#include "spinhash/config.hpp"

using namespace spinhash;

namespace {

OrientedPoint op(float x, float y, float z, Eigen::Vector3f n) {
  return OrientedPoint{Eigen::Vector3f(x, y, z), n.normalized()};
}

OrientedPoint moved(const OrientedPoint& m, const Eigen::Matrix3f& r, const Eigen::Vector3f& t) {
  return OrientedPoint{r * m.p + t, r * m.n};
}

Eigen::Matrix3f known_rotation() {
  return (Eigen::AngleAxisf(0.7f, Eigen::Vector3f(0.3f, -0.5f, 0.8f).normalized())).toRotationMatrix();
}

}  // namespace

TEST_CASE("a known rotation and translation are recovered from two oriented correspondences") {
  const Eigen::Matrix3f r = known_rotation();
  const Eigen::Vector3f t(12.5f, -3.0f, 0.75f);
  OrientedPoint m1 = op(0.4f, 0.2f, 1.1f, Eigen::Vector3f(0.1f, 0.2f, 1.0f));
  OrientedPoint m2 = op(-1.3f, 0.9f, 0.6f, Eigen::Vector3f(-1.0f, 0.3f, 0.2f));
  RigidPose pose;
  REQUIRE(pose_from_doublet(moved(m1, r, t), moved(m2, r, t), m1, m2, &pose, DrawsParams{}.normal_lever));
  CHECK((pose.rotation - r).norm() < 1e-4f);
  CHECK((pose.translation - t).norm() < 1e-4f);
  CHECK(pose.rotation.determinant() == doctest::Approx(1.0f).epsilon(1e-5));
}

TEST_CASE("the pose degrades gracefully with noisy normals") {
  const Eigen::Matrix3f r = known_rotation();
  const Eigen::Vector3f t(1.0f, 2.0f, 3.0f);
  OrientedPoint m1 = op(0.0f, 0.0f, 0.0f, Eigen::Vector3f(0, 0, 1));
  OrientedPoint m2 = op(2.0f, 0.0f, 0.0f, Eigen::Vector3f(1, 0, 0));
  OrientedPoint q1 = moved(m1, r, t), q2 = moved(m2, r, t);
  q1.n = (q1.n + Eigen::Vector3f(0.05f, 0.0f, 0.0f)).normalized();  // about 3 degrees off
  RigidPose pose;
  REQUIRE(pose_from_doublet(q1, q2, m1, m2, &pose, DrawsParams{}.normal_lever));
  float angle = Eigen::AngleAxisf(pose.rotation * r.transpose()).angle();
  CHECK(angle < 0.06f);
}

TEST_CASE("coincident points give no doublet and no pose") {
  OrientedPoint a = op(1, 1, 1, Eigen::Vector3f(0, 0, 1));
  OrientedPoint b = op(1, 1, 1, Eigen::Vector3f(1, 0, 0));
  DoubletShape s;
  CHECK_FALSE(doublet_shape(a, b, &s));
}

TEST_CASE("the cascade passes a rigidly moved pair and rejects each kind of mismatch in order") {
  OrientedPoint m1 = op(0.0f, 0.0f, 0.0f, Eigen::Vector3f(0.2f, 0.1f, 1.0f));
  OrientedPoint m2 = op(1.5f, 0.4f, 0.2f, Eigen::Vector3f(0.9f, -0.6f, 0.3f));
  const Eigen::Matrix3f r = known_rotation();
  const Eigen::Vector3f t(5, 6, 7);
  DoubletShape q;
  REQUIRE(doublet_shape(moved(m1, r, t), moved(m2, r, t), &q));
  DoubletTolerance tol;  // 0.3 m, 0.44 rad, 0.5
  CHECK(check_doublet(q, m1, m2, tol) == CascadeStage::kPass);

  OrientedPoint far = m2;
  far.p += Eigen::Vector3f(1.0f, 0.0f, 0.0f);
  CHECK(check_doublet(q, m1, far, tol) == CascadeStage::kDistance);  // d is tested first

  OrientedPoint turned = m2;
  turned.n = Eigen::Vector3f(-0.9f, 0.6f, -0.3f).normalized();
  CHECK(check_doublet(q, m1, turned, tol) == CascadeStage::kAngleA);
}

TEST_CASE("the cascade rejects a mirrored pair that matches d, a, b and c exactly") {
  OrientedPoint m1 = op(0.0f, 0.0f, 0.0f, Eigen::Vector3f(0.0f, 0.6f, 0.8f));
  OrientedPoint m2 = op(2.0f, 0.0f, 0.0f, Eigen::Vector3f(0.0f, -0.8f, 0.6f));
  DoubletShape q;
  REQUIRE(doublet_shape(m1, m2, &q));
  REQUIRE(std::fabs(q.t) > 0.5f);  // clearly handed: normals span a plane across u
  // Mirror through the plane y = 0: distances and angles are unchanged.
  Eigen::Matrix3f mirror = Eigen::Vector3f(1.0f, -1.0f, 1.0f).asDiagonal();
  OrientedPoint w1{mirror * m1.p, mirror * m1.n}, w2{mirror * m2.p, mirror * m2.n};
  DoubletShape w;
  REQUIRE(doublet_shape(w1, w2, &w));
  CHECK(w.d == doctest::Approx(q.d));
  CHECK(w.a == doctest::Approx(q.a));
  CHECK(w.b == doctest::Approx(q.b));
  CHECK(w.c == doctest::Approx(q.c));
  CHECK(w.t == doctest::Approx(-q.t));
  CHECK(check_doublet(q, w1, w2, DoubletTolerance{}) == CascadeStage::kHandedness);
}

TEST_CASE("stability constraints of eq. 3") {
  DoubletShape s;
  s.d = 0.4f;
  s.a = 0.5f;
  CHECK_FALSE(is_stable(s, 0.5f, 0.17f));
  s.d = 0.8f;
  CHECK(is_stable(s, 0.5f, 0.17f));
  s.a = 0.1f;
  CHECK_FALSE(is_stable(s, 0.5f, 0.17f));
}
