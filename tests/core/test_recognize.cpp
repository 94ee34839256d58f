// End to end on the target: a database built in-process, a partial, moved,
// noisy view of each model, recognised by BRAN, SRAN and SIND.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_database.hpp"

#ifdef EIGEN_RUNTIME_NO_MALLOC
#include <Eigen/Core>
#endif

using namespace spinhash;

namespace {

struct Session {
  const test::ToyDatabase* toy = &test::shared_toy_database();
  host::AlignedBytes workspace;
  Recognizer recognizer;
  Status init(const RecognizerConfig& cfg) {
    workspace = host::AlignedBytes(required_workspace_bytes(cfg));
    return recognizer.init(&toy->db, cfg, workspace.data(), workspace.size());
  }
};

Result recognize_without_heap(Recognizer& r, const std::vector<double>& q) {
#ifdef EIGEN_RUNTIME_NO_MALLOC
  Eigen::internal::set_is_malloc_allowed(false);  // any Eigen allocation now asserts
#endif
  Result res = r.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
#ifdef EIGEN_RUNTIME_NO_MALLOC
  Eigen::internal::set_is_malloc_allowed(true);
#endif
  return res;
}

}  // namespace

TEST_CASE("each toy model is recognised first from its own partial, moved, noisy view") {
  Session s;
  for (Mode mode : {Mode::kBran, Mode::kSran, Mode::kSind}) {
    RecognizerConfig cfg;
    cfg.mode = mode;
    REQUIRE(s.init(cfg) == Status::kOk);
    for (uint32_t m = 0; m < test::kToyModels; ++m) {
      const double t[3] = {431000.5, 4020000.25, 87.0};  // UTM-like: only double keeps centimetres
      std::vector<double> q = test::toy_query(test::toy_vehicle_points(m, 0.05f), 0.4 + m, t, 0.03, m + 1);
      Result r = recognize_without_heap(s.recognizer, q);
      CAPTURE(static_cast<int>(mode));
      CAPTURE(m);
      REQUIRE(r.status == Status::kOk);
      REQUIRE(r.ranking_count >= 1);
      if (mode == Mode::kSind) {  // the baseline without geometry: near the top, not always first
        bool top3 = false;
        for (uint32_t i = 0; i < r.ranking_count && i < 3; ++i) top3 = top3 || r.ranking[i].model == m;
        CHECK(top3);
        continue;
      }
      CHECK(r.ranking[0].model == m);
      CHECK(r.ranking[0].has_pose);
      if (mode == Mode::kSran) continue;  // near-symmetric toys: SRAN's fewer hypotheses may settle on a flip
      // The pose maps the model frame onto the georeferenced query.
      const Pose& p = r.ranking[0].pose;
      double yaw = std::atan2(static_cast<double>(p.rotation[3]), static_cast<double>(p.rotation[0]));
      double dyaw = std::remainder(yaw - (0.4 + m), 2.0 * 3.14159265358979);
      CHECK(std::fabs(dyaw) < 0.1);
      CHECK(std::fabs(p.translation[0] - t[0]) < 0.3);
      CHECK(std::fabs(p.translation[1] - t[1]) < 0.3);
      CHECK(std::fabs(p.translation[2] - t[2]) < 0.3);
    }
  }
}

TEST_CASE("recognition is deterministic for a seed and reports its work") {
  Session s;
  RecognizerConfig cfg;
  REQUIRE(s.init(cfg) == Status::kOk);
  const double t[3] = {0, 0, 0};
  std::vector<double> q = test::toy_query(test::toy_vehicle_points(2, 0.05f), 1.0, t, 0.03, 7);
  Result a = recognize_without_heap(s.recognizer, q);
  std::vector<RankedModel> first(a.ranking, a.ranking + a.ranking_count);
  Result b = recognize_without_heap(s.recognizer, q);
  REQUIRE(a.ranking_count == b.ranking_count);
  for (uint32_t i = 0; i < b.ranking_count; ++i) {
    CHECK(first[i].model == b.ranking[i].model);
    CHECK(first[i].score == b.ranking[i].score);
  }
  CHECK(b.stats.extract.features > 10);
  CHECK(b.stats.draws.hypotheses > 0);
  CHECK(b.stats.draws.doublets_passed >= b.stats.draws.hypotheses);
  CHECK(b.stats.draws.pair_checks >= b.stats.draws.doublets_passed);
  CHECK(b.stats.workspace_used <= s.workspace.size());
}

TEST_CASE("the work budget stops recognition and says so") {
  Session s;
  RecognizerConfig cfg;
  cfg.draws.max_hypotheses = 3;
  REQUIRE(s.init(cfg) == Status::kOk);
  const double t[3] = {0, 0, 0};
  std::vector<double> q = test::toy_query(test::toy_vehicle_points(0, 0.05f), 0.0, t, 0.0, 1);
  Result r = recognize_without_heap(s.recognizer, q);
  REQUIRE(r.status == Status::kOk);
  CHECK(r.stats.draws.budget_exhausted);
  CHECK(r.stats.draws.hypotheses == 3);
}

TEST_CASE("a blob built without the nearest-feature field recognises the toys as one with it") {
  Session with, without;
  host::BuildOptions no_field;
  no_field.field.cell = 0.0f;  // spinhash build --field-cell 0
  test::ToyDatabase fieldless;
  REQUIRE(test::make_database(test::toy_clouds(), &fieldless, no_field));
  without.toy = &fieldless;
  CHECK(with.toy->db.has_nearest_field());
  CHECK_FALSE(without.toy->db.has_nearest_field());
  CHECK(without.toy->bytes.size() < with.toy->bytes.size());
  RecognizerConfig cfg;
  REQUIRE(with.init(cfg) == Status::kOk);
  REQUIRE(without.init(cfg) == Status::kOk);
  for (uint32_t m = 0; m < test::kToyModels; ++m) {
    const double t[3] = {12.0, -3.0, 0.5};
    std::vector<double> q = test::toy_query(test::toy_vehicle_points(m, 0.05f), 0.3 + m, t, 0.03, m + 11);
    Result a = recognize_without_heap(with.recognizer, q);
    Result b = recognize_without_heap(without.recognizer, q);
    CAPTURE(m);
    REQUIRE(a.ranking_count >= 1);
    REQUIRE(b.ranking_count >= 1);
    CHECK(a.ranking[0].model == m);
    CHECK(b.ranking[0].model == m);  // the exact grid search throughout
    for (int k = 0; k < 3; ++k)
      CHECK(std::fabs(a.ranking[0].pose.translation[k] - b.ranking[0].pose.translation[k]) < 0.15);
  }
}
