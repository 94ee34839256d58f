// A stage switched off (its `enabled` field, stage_fields.h) is skipped: the
// answer is the one its own count at 0 gives, and the stage counts nothing;
// ablations are configuration. Over the golden blob and queries (quick on
// every target).
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "golden/golden_expected.hpp"
#include "spinhash/recognizer.hpp"
#include "support/golden_files.hpp"

using namespace spinhash;

namespace {

struct Answer {
  Status status;
  std::vector<RankedModel> ranking;
  RecognitionStats stats;
};

Answer recognise(const Database& db, const RecognizerConfig& cfg, const std::vector<float>& xyz) {
  host::AlignedBytes workspace(required_workspace_bytes(cfg));
  Recognizer rec;
  REQUIRE(rec.init(&db, cfg, workspace.data(), workspace.size()) == Status::kOk);
  const Result r = rec.recognize(xyz.data(), static_cast<uint32_t>(xyz.size() / 3));
  Answer a{r.status, {}, r.stats};
  for (uint32_t i = 0; i < r.ranking_count; ++i) a.ranking.push_back(r.ranking[i]);
  return a;
}

void check_same(const Answer& a, const Answer& b) {
  REQUIRE(a.status == b.status);
  REQUIRE(a.ranking.size() == b.ranking.size());
  for (size_t i = 0; i < a.ranking.size(); ++i) {
    CAPTURE(i);
    CHECK(a.ranking[i].model == b.ranking[i].model);
    CHECK(std::memcmp(&a.ranking[i].score, &b.ranking[i].score, sizeof(float)) == 0);
  }
  CHECK(a.stats.draws.trials == b.stats.draws.trials);
  CHECK(a.stats.draws.hypotheses == b.stats.draws.hypotheses);
}

// Golden query q's points, on a plane of ground 3 m around them (0.15 m grid).
std::vector<float> on_ground(const std::vector<float>& all, const golden::GoldenQuery& q) {
  std::vector<float> pts(all.begin() + 3 * q.first_point, all.begin() + 3 * (q.first_point + q.point_count));
  float lo[3] = {1e9f, 1e9f, 1e9f}, hi[3] = {-1e9f, -1e9f, -1e9f};
  for (size_t i = 0; i < pts.size(); i += 3)
    for (int a = 0; a < 3; ++a)
      lo[a] = pts[i + a] < lo[a] ? pts[i + a] : lo[a], hi[a] = pts[i + a] > hi[a] ? pts[i + a] : hi[a];
  for (float x = lo[0] - 3.0f; x < hi[0] + 3.0f; x += 0.15f)
    for (float y = lo[1] - 3.0f; y < hi[1] + 3.0f; y += 0.15f) pts.insert(pts.end(), {x, y, lo[2] - 0.02f});
  return pts;
}

}  // namespace

TEST_CASE("stage switches: transfer, focus and ground off are their counts at 0, and count nothing") {
  host::AlignedBytes blob = test::golden_blob(true);
  Database db;
  REQUIRE(Database::open(blob.data(), blob.size(), &db) == Status::kOk);
  const std::vector<float> all = test::golden_query_points();
  const golden::GoldenQuery& q = golden::kGoldenQueries[0];
  const std::vector<float> xyz = on_ground(all, q);
  const RecognizerConfig base = golden::golden_config(Mode::kBran);

  const Answer with_ground = recognise(db, base, xyz);
  REQUIRE(with_ground.stats.ground.points_ground > 0u);  // the plane is found and dropped
  RecognizerConfig no_ground = base, zero_clearance = base;
  no_ground.ground.enabled = false;
  zero_clearance.ground.ground_clearance = 0.0f;
  const Answer off = recognise(db, no_ground, xyz);
  CHECK(off.stats.ground.points_ground == 0u);
  check_same(off, recognise(db, zero_clearance, xyz));

  RecognizerConfig no_transfer = base, zero_transfer = base;
  no_transfer.transfer.enabled = false;
  zero_transfer.transfer.transfer_models = 0;
  const Answer untransferred = recognise(db, no_transfer, xyz);
  CHECK(untransferred.stats.transfer.transferred == 0u);
  check_same(untransferred, recognise(db, zero_transfer, xyz));
  CHECK(with_ground.stats.transfer.transferred > 0u);  // on, the stage did lend poses

  RecognizerConfig no_focus = base, zero_focus = base;
  no_focus.focus.enabled = false;
  zero_focus.focus.focus_models = 0;
  check_same(recognise(db, no_focus, xyz), recognise(db, zero_focus, xyz));
}
