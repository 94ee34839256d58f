// Eqs. 4-7 as verify_pose computes them, and the least-squares refinement,
// on a query made of a toy model's own features under a known pose.
#include <doctest/doctest.h>

#include <cmath>

#include "match/likelihood.hpp"
#include "match/refine_pose.hpp"
#include "support/model_features_query.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kModel = 1;
constexpr float kDegree = 3.14159265f / 180.0f;
constexpr int kRefineSteps = 6;  // further least-squares steps after the first

struct Fixture {
  test::ToyDatabase toy;
  RecognizerConfig cfg;
  LikelihoodParams lp;
  RigidPose truth = test::make_pose(0.7f, 0.05f, Eigen::Vector3f(3.0f, -2.0f, 1.0f));
  test::ModelFeatureQuery q;
  Fixture() {
    REQUIRE(test::make_toy_database(&toy));
    lp = make_likelihood_params(cfg, toy.db);
    REQUIRE(lp.use_field);  // the toy blob has a field; these pin the exact search (finalisation's)
    lp.use_field = false;
    test::model_feature_query(toy.db, kModel, truth, &q);
    REQUIRE(q.view.count > 50u);
  }
};

float angle_between(const Eigen::Matrix3f& a, const Eigen::Matrix3f& b) {
  const float c = 0.5f * ((a.transpose() * b).trace() - 1.0f);
  return std::acos(c > 1.0f ? 1.0f : (c < -1.0f ? -1.0f : c));
}

}  // namespace

TEST_CASE_FIXTURE(Fixture, "the exact pose explains every feature at the likelihood's maximum") {
  const Verification v = verify_pose(toy.db, kModel, truth, q.view, lp, kNoScoreToBeat, kNoScoreToBeat);
  CHECK(v.complete);
  CHECK(v.inliers == q.view.count);
  // Each term is -r^2 / (2 sigma^2) - L1 / lambda with r ~ 1e-6 m and L1 = 0: the maximum, 0.
  CHECK(v.log_likelihood <= 0.0f);
  CHECK(v.log_likelihood > -1e-3f * static_cast<float>(q.view.count));
}

TEST_CASE_FIXTURE(Fixture, "a pose far from the model gives every feature the floor term exactly") {
  RigidPose far = truth;
  far.translation += Eigen::Vector3f(500.0f, 0.0f, 0.0f);
  const Verification v = verify_pose(toy.db, kModel, far, q.view, lp, kNoScoreToBeat, kNoScoreToBeat);
  CHECK(v.complete);
  CHECK(v.inliers == 0u);
  CHECK(lp.floor < 0.0f);
  CHECK(v.log_likelihood == doctest::Approx(lp.floor * static_cast<float>(q.view.count)).epsilon(1e-5));
}

TEST_CASE_FIXTURE(Fixture, "verification stops as soon as the score to beat is out of reach") {
  // Terms are <= 0, so nothing beats +1: stopped before the first feature.
  const Verification v = verify_pose(toy.db, kModel, truth, q.view, lp, 1.0f, kNoScoreToBeat);
  CHECK_FALSE(v.complete);
  CHECK(v.inliers == 0u);
  // Preemption drops a far pose against the exact pose's score at its first checkpoint.
  RigidPose far = truth;
  far.translation += Eigen::Vector3f(500.0f, 0.0f, 0.0f);
  const float exact =
      verify_pose(toy.db, kModel, truth, q.view, lp, kNoScoreToBeat, kNoScoreToBeat).log_likelihood;
  const Verification pre = verify_pose(toy.db, kModel, far, q.view, lp, exact, exact);
  CHECK_FALSE(pre.complete);
}

TEST_CASE_FIXTURE(Fixture, "another model explains the query worse than its own") {
  const float own =
      verify_pose(toy.db, kModel, truth, q.view, lp, kNoScoreToBeat, kNoScoreToBeat).log_likelihood;
  const float other =
      verify_pose(toy.db, kModel + 1u, truth, q.view, lp, kNoScoreToBeat, kNoScoreToBeat).log_likelihood;
  CHECK(other < own - 0.5f * static_cast<float>(q.view.count));
}

TEST_CASE_FIXTURE(Fixture, "refine_pose, repeated, recovers the pose from a perturbed one") {
  // 1.5 degrees about a tilted axis and 6 cm: most features find their own counterpart at once.
  RigidPose start = truth;
  start.rotation =
      Eigen::AngleAxisf(1.5f * kDegree, Eigen::Vector3f(0.3f, 0.5f, 0.8f).normalized()) * truth.rotation;
  start.translation += Eigen::Vector3f(0.04f, -0.03f, 0.03f);
  REQUIRE(angle_between(start.rotation, truth.rotation) > 1.4f * kDegree);
  RigidPose refined = start;
  REQUIRE(refine_pose(toy.db, kModel, q.view, lp, &refined));
  CHECK(angle_between(refined.rotation, truth.rotation) <
        0.5f * angle_between(start.rotation, truth.rotation));
  CHECK((refined.translation - truth.translation).norm() <
        0.5f * (start.translation - truth.translation).norm());
  for (int step = 0; step < kRefineSteps; ++step) REQUIRE(refine_pose(toy.db, kModel, q.view, lp, &refined));
  CHECK(angle_between(refined.rotation, truth.rotation) < 0.05f * kDegree);
  CHECK((refined.translation - truth.translation).norm() < 1e-3f);
}

TEST_CASE_FIXTURE(Fixture, "refine_pose keeps a pose that matches too few features") {
  RigidPose far = truth;
  far.translation += Eigen::Vector3f(500.0f, 0.0f, 0.0f);
  RigidPose kept = far;
  CHECK_FALSE(refine_pose(toy.db, kModel, q.view, lp, &kept));
  CHECK(kept.translation == far.translation);
}
