// Eqs. 4-7 as verify_pose computes them, and the least-squares refinement,
// on a query made of a toy model's own features under a known pose.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "match/likelihood.hpp"
#include "match/refine_pose.hpp"
#include "support/model_features_query.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

const float kDamping = RefineParams{}.damping_per_match;

constexpr uint32_t kModel = 1;
constexpr float kDegree = 3.14159265f / 180.0f;
constexpr int kRefineSteps = 6;  // further least-squares steps after the first

struct Fixture {
  const test::ToyDatabase& toy = test::shared_toy_database();
  RecognizerConfig cfg;
  LikelihoodParams lp;
  RigidPose truth = test::make_pose(0.7f, 0.05f, Eigen::Vector3f(3.0f, -2.0f, 1.0f));
  test::ModelFeatureQuery q;
  Fixture() {
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
  REQUIRE(refine_pose(toy.db, kModel, q.view, lp, &refined, nullptr, kDamping));
  CHECK(angle_between(refined.rotation, truth.rotation) <
        0.5f * angle_between(start.rotation, truth.rotation));
  CHECK((refined.translation - truth.translation).norm() <
        0.5f * (start.translation - truth.translation).norm());
  for (int step = 0; step < kRefineSteps; ++step)
    REQUIRE(refine_pose(toy.db, kModel, q.view, lp, &refined, nullptr, kDamping));
  CHECK(angle_between(refined.rotation, truth.rotation) < 0.05f * kDegree);
  CHECK((refined.translation - truth.translation).norm() < 1e-3f);
}

TEST_CASE_FIXTURE(Fixture,
                  "refine_pose from verify_pose's recorded matches takes the same step as its own search") {
  // 8 degrees and 30 cm: part of the features match a neighbour or nothing
  // within Delta, so the recorded matches are not simply "each its own".
  RigidPose start = truth;
  start.rotation =
      Eigen::AngleAxisf(8.0f * kDegree, Eigen::Vector3f(0.2f, -0.4f, 0.9f).normalized()) * truth.rotation;
  start.translation += Eigen::Vector3f(0.25f, -0.15f, 0.1f);
  std::vector<int32_t> matches(q.view.count, 12345);
  const Verification v =
      verify_pose(toy.db, kModel, start, q.view, lp, kNoScoreToBeat, kNoScoreToBeat, matches.data());
  REQUIRE(v.complete);
  uint32_t matched = 0;
  for (int32_t m : matches) {
    CHECK(m != 12345);  // every feature visited and written
    matched += m != kNoMatch ? 1u : 0u;
  }
  CHECK(matched == v.inliers);
  CHECK(matched < q.view.count);
  RigidPose searched = start, reused = start;
  REQUIRE(refine_pose(toy.db, kModel, q.view, lp, &searched, nullptr, kDamping));
  REQUIRE(refine_pose(toy.db, kModel, q.view, lp, &reused, matches.data(), kDamping));
  CHECK(reused.rotation == searched.rotation);  // bit for bit: the same sums in the same order
  CHECK(reused.translation == searched.translation);
}

TEST_CASE_FIXTURE(Fixture, "refine_pose keeps a pose that matches too few features") {
  RigidPose far = truth;
  far.translation += Eigen::Vector3f(500.0f, 0.0f, 0.0f);
  RigidPose kept = far;
  CHECK_FALSE(refine_pose(toy.db, kModel, q.view, lp, &kept, nullptr, kDamping));
  CHECK(kept.translation == far.translation);
}

TEST_CASE_FIXTURE(
    Fixture, "the surface residual: along the normal it counts, along the surface only beyond the patch") {
  const LikelihoodParams surface = make_surface_params(cfg, toy.db);
  REQUIRE_FALSE(surface.use_field);
  CHECK(surface.surface_patch_radius ==
        doctest::Approx(cfg.refine.patch_radius_per_spacing * toy.db.params().basis_spacing));
  CHECK(surface.inv_two_sigma2 ==
        doctest::Approx(1.0f / (2.0f * cfg.refine.sigma_surface * cfg.refine.sigma_surface)));
  CHECK(surface.floor == lp.floor);  // an unexplained feature costs what it cost in the hypothesis loop
  const uint32_t f = toy.db.model(kModel).first_feature;
  const Eigen::Vector3f p = Eigen::Map<const Eigen::Vector3f>(toy.db.positions() + 3u * f);
  const int16_t* n16 = toy.db.normals() + 3u * f;
  const Eigen::Vector3f n(decode_normal_component(n16[0]), decode_normal_component(n16[1]),
                          decode_normal_component(n16[2]));
  const Eigen::Vector3f along = n.unitOrthogonal();  // a direction in the tangent plane
  const float radius = surface.surface_patch_radius;
  auto r2 = [&](const Eigen::Vector3f& x, const LikelihoodParams& params) {
    return residual2(toy.db, f, x, (x - p).squaredNorm(), params);
  };
  CHECK(r2(p + 0.8f * radius * along, surface) == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK(r2(p + (radius + 0.05f) * along, surface) == doctest::Approx(0.05f * 0.05f).epsilon(1e-3));
  CHECK(r2(p + 0.07f * n, surface) == doctest::Approx(0.07f * 0.07f).epsilon(1e-3));
  CHECK(r2(p + 0.07f * n + 0.5f * radius * along, surface) == doctest::Approx(0.07f * 0.07f).epsilon(1e-3));
  // The paper's r: the distance to the feature itself.
  CHECK(r2(p + 0.8f * radius * along, lp) == doctest::Approx(0.64f * radius * radius).epsilon(1e-4));
}

TEST_CASE_FIXTURE(Fixture, "refine_pose on one flat face corrects across it and does not slide along it") {
  // Only the features facing up on the upper half (the toy's box bottoms,
  // never seen from the air, face up too): the pose is fixed across the face
  // (z, tilt) and free along it; the step must not move along it.
  const blob::ModelRecord& rec = toy.db.model(kModel);
  test::ModelFeatureQuery top;
  const Eigen::Matrix3f rt = truth.rotation.transpose();
  const float mid_height = 0.5f * (rec.bbox_min[2] + rec.bbox_max[2]);
  for (uint32_t i = 0; i < q.view.count; ++i) {
    const Eigen::Vector3f n = rt * Eigen::Map<const Eigen::Vector3f>(q.normals.data() + 3u * i);
    const Eigen::Vector3f x =
        rt * (Eigen::Map<const Eigen::Vector3f>(q.positions.data() + 3u * i) - truth.translation);
    if (n.z() < 0.99f || x.z() < mid_height) continue;
    // 1 cm of scatter, as range noise: the normals' few-degree spread turns
    // it into a pull along the face that only the damping holds.
    for (uint32_t a = 0; a < 3; ++a)
      top.positions.push_back(q.positions[3u * i + a] +
                              0.01f * std::sin(12.9898f * static_cast<float>(3u * i + a)));
    top.normals.insert(top.normals.end(), q.normals.begin() + 3 * i, q.normals.begin() + 3 * i + 3);
    top.spins.insert(top.spins.end(), q.spins.begin() + static_cast<std::ptrdiff_t>(i * q.view.dims),
                     q.spins.begin() + static_cast<std::ptrdiff_t>((i + 1) * q.view.dims));
  }
  top.view = q.view;
  top.view.positions = top.positions.data();
  top.view.normals = top.normals.data();
  top.view.spins = top.spins.data();
  top.view.count = top.view.verify_count = static_cast<uint32_t>(top.positions.size() / 3);
  REQUIRE(top.view.count >= kMinRefineMatches);
  REQUIRE(top.view.count < rec.feature_count);
  RigidPose start = truth;
  start.translation += truth.rotation * Eigen::Vector3f(0.0f, 0.0f, 0.06f);  // 6 cm above the roof
  RigidPose refined = start;
  REQUIRE(refine_pose(toy.db, kModel, top.view, lp, &refined, nullptr, kDamping));
  const Eigen::Vector3f moved = rt * (refined.translation - start.translation);
  CHECK(moved.z() == doctest::Approx(-0.06f).epsilon(0.1));  // down onto the roof
  CHECK(std::abs(moved.x()) < 0.01f);                        // not along it
  CHECK(std::abs(moved.y()) < 0.01f);
  CHECK(angle_between(refined.rotation, truth.rotation) < 0.5f * kDegree);
}

TEST_CASE_FIXTURE(
    Fixture, "a pose turned end to end: same footprint, the other way round, and refinement stays there") {
  const RigidPose turned = turned_end_to_end(truth, toy.db.model(kModel));
  const RigidPose back = turned_end_to_end(turned, toy.db.model(kModel));
  CHECK(angle_between(back.rotation, truth.rotation) < 1e-3f);
  CHECK((back.translation - truth.translation).norm() < 1e-4f);
  CHECK(angle_between(turned.rotation, truth.rotation) == doctest::Approx(3.14159265f).epsilon(1e-3));
  // The box's centre stays where it was.
  const blob::ModelRecord& rec = toy.db.model(kModel);
  const Eigen::Vector3f centre(0.5f * (rec.bbox_min[0] + rec.bbox_max[0]),
                               0.5f * (rec.bbox_min[1] + rec.bbox_max[1]), 0.0f);
  CHECK(
      (turned.rotation * centre + turned.translation - (truth.rotation * centre + truth.translation)).norm() <
      1e-4f);
  // The toy's cabin sits off centre: turned, it explains the query far worse,
  // and least squares from there do not find the way back (a local search).
  const LikelihoodParams surface = make_surface_params(cfg, toy.db);
  const float right =
      verify_pose(toy.db, kModel, truth, q.view, surface, kNoScoreToBeat, kNoScoreToBeat).log_likelihood;
  RigidPose refined = turned;
  for (int step = 0; step < kRefineSteps; ++step)
    refine_pose(toy.db, kModel, q.view, surface, &refined, nullptr, kDamping);
  CHECK(angle_between(refined.rotation, truth.rotation) > 90.0f * kDegree);
  const float stuck =
      verify_pose(toy.db, kModel, refined, q.view, surface, kNoScoreToBeat, kNoScoreToBeat).log_likelihood;
  CHECK(stuck < right - 0.5f * static_cast<float>(q.view.count));
}
