// Look-alike pose transfer (recognize/pose_transfer.cpp): a model crowded out
// of the W candidates by an identical twin still gets the twin's pose, and an
// answer tied with its twin is not confident.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kTwinned = 2;  // toy-2 gets an exact twin, the database's last model

// Recognises a moved, noisy view of toy-2 with W = 1: each query feature's
// single candidate is toy-2's copy of a feature (equal distances go to the
// lower feature index), so the twin never takes part in a doublet.
struct Twinned {
  test::ToyDatabase toy;
  host::AlignedBytes ws;
  const uint32_t twin = test::kToyModels;
  Twinned() { REQUIRE(test::make_toy_database(&toy, kTwinned)); }

  Result recognize(uint32_t transfer_models) {
    RecognizerConfig cfg;
    cfg.top_w = 1;
    cfg.transfer_models = transfer_models;
    ws = host::AlignedBytes(required_workspace_bytes(cfg));
    Recognizer r;
    REQUIRE(r.init(&toy.db, cfg, ws.data(), ws.size()) == Status::kOk);
    const double t[3] = {120.0, -40.0, 3.0};
    std::vector<double> q = test::toy_query(test::toy_vehicle_points(kTwinned, 0.05f), 0.7, t, 0.03, 5);
    Result res = r.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
    REQUIRE(res.status == Status::kOk);
    return res;
  }
};

const RankedModel* find(const Result& r, uint32_t model) {
  for (uint32_t i = 0; i < r.ranking_count; ++i)
    if (r.ranking[i].model == model) return &r.ranking[i];
  return nullptr;
}

}  // namespace

TEST_CASE_FIXTURE(Twinned, "a twin crowded out of the candidates gets no pose without transfer") {
  Result r = recognize(0);
  REQUIRE(r.ranking_count >= 1);
  CHECK(r.ranking[0].model == kTwinned);
  const RankedModel* t = find(r, twin);
  CHECK((t == nullptr || !t->has_pose));
}

TEST_CASE_FIXTURE(Twinned, "pose transfer scores the twin at the leading pose, as well as the original") {
  Result r = recognize(8);
  REQUIRE(r.ranking_count >= 2);
  // Identical geometry at an identical pose: the two lead, with equal scores.
  CHECK(((r.ranking[0].model == kTwinned && r.ranking[1].model == twin) ||
         (r.ranking[0].model == twin && r.ranking[1].model == kTwinned)));
  const RankedModel* a = find(r, kTwinned);
  const RankedModel* b = find(r, twin);
  REQUIRE(a != nullptr);
  REQUIRE(b != nullptr);
  CHECK(b->has_pose);
  CHECK(std::fabs(a->score - b->score) <= 1e-3f * std::fabs(a->score));
  for (int k = 0; k < 3; ++k) CHECK(std::fabs(a->pose.translation[k] - b->pose.translation[k]) < 0.05);
  CHECK(std::fabs(a->pose.rotation[0] - b->pose.rotation[0]) < 0.01f);
  CHECK(std::fabs(a->pose.rotation[3] - b->pose.rotation[3]) < 0.01f);
}

TEST_CASE_FIXTURE(Twinned, "an answer its exact twin ties is not confident, whatever its fit") {
  Result r = recognize(8);
  REQUIRE(r.ranking_count >= 2);
  CHECK_FALSE(r.confident);  // the lead over the runner-up (the twin) is 0 < min_margin
  CHECK(r.ranking[0].inliers * 2u >= r.stats.features);  // the fit itself would pass
}

TEST_CASE_FIXTURE(Twinned, "without its twin in the running the same fit is confident") {
  Result r = recognize(0);
  REQUIRE(r.ranking_count >= 1);
  CHECK(r.ranking[0].model == kTwinned);
  CHECK(r.confident);
}
