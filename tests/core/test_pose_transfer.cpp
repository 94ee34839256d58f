// Look-alike pose transfer (recognize/pose_transfer.cpp): a model crowded out
// of the W candidates by an identical twin still gets the twin's pose, and an
// answer tied with its twin is not confident: its look-alike group holds both.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kTwinned = 2;   // toy-2 gets an exact twin, the database's last model
constexpr float kUnpinned = 1e6f;  // m: max_extent_shortfall that never withholds confidence

// Recognises a moved, noisy view of toy-2 with W = 1: each query feature's
// single candidate is toy-2's copy of a feature (equal distances go to the
// lower feature index), so the twin never takes part in a doublet.
struct Twinned {
  test::ToyDatabase toy;
  host::AlignedBytes ws;
  const uint32_t twin = test::kToyModels;
  Twinned() { REQUIRE(test::make_toy_database(&toy, kTwinned)); }

  Result recognize(uint32_t transfer_models, RecognizerConfig cfg = RecognizerConfig{}) {
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
  CHECK_FALSE(r.confident);               // the lead over the runner-up (the twin) is 0 < min_margin
  CHECK(r.group_size >= 2u);              // ... so the answer is the look-alike group: the twins, first
  CHECK(r.group_size < r.ranking_count);  // not every model: the toys differ by more than the margin
  CHECK(r.ranking[0].inliers * 2u >= r.stats.features);  // the fit itself would pass
}

TEST_CASE_FIXTURE(Twinned, "without its twin in the running the same fit is confident") {
  // toy_query's view stops short of the hull's right side, which a wider
  // look-alike could have: not what this case is about (test_confidence.cpp).
  RecognizerConfig cfg;
  cfg.max_extent_shortfall = kUnpinned;
  Result r = recognize(0, cfg);
  REQUIRE(r.ranking_count >= 1);
  CHECK(r.ranking[0].model == kTwinned);
  CHECK(r.group_size == 1u);
  CHECK(r.confident);
}

TEST_CASE_FIXTURE(Twinned, "the look-alike group is every leading model within min_margin of the first") {
  RecognizerConfig cfg;
  for (float margin : {0.0f, 2.1f, 20.0f, 1e4f}) {
    CAPTURE(margin);
    cfg.min_margin = margin;
    Result r = recognize(8, cfg);
    REQUIRE(r.ranking_count >= 2);
    const float within = margin * std::sqrt(static_cast<float>(r.stats.features));
    uint32_t expected = 1;
    while (expected < r.ranking_count && r.ranking[0].score - r.ranking[expected].score < within) ++expected;
    CHECK(r.group_size == expected);
    if (margin >= 1e4f) CHECK(r.group_size == r.ranking_count);  // nothing is that far behind
    if (margin == 0.0f) CHECK(r.group_size == 1u);
  }
  // A margin that just takes in the third model (its gap is 3/4 of it).
  Result first = recognize(8);
  REQUIRE(first.ranking_count >= 3);
  const float gap = first.ranking[0].score - first.ranking[2].score;
  const float root = std::sqrt(static_cast<float>(first.stats.features));
  cfg.min_margin = gap / (0.75f * root);
  CHECK(recognize(8, cfg).group_size >= 3u);
  cfg.min_margin = gap / (1.25f * root);  // ... and one that just leaves it out
  CHECK(recognize(8, cfg).group_size == 2u);
}
