// What BRAN does when the candidates are spread over many look-alikes:
// - look-alike doublets (recognize/bran.cpp): a doublet may pair candidates
//   of two models whose boxes nearly coincide; bounded per draw; models
//   whose boxes lie apart never pair; the paper's BRAN
//   (lookalike_box_l1 = 0) never does;
// - the first model's refined pose lent to its nearest look-alikes at the
//   end (recognize/refinement.cpp), which then score as it does.
#include <doctest/doctest.h>

#include <list>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_copies.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kCopies = 40;   // a feature's W = 50 candidates name most of them
constexpr uint32_t kTrials = 200;  // draws, all of them made (no stop, no extension)
const uint32_t kPairsPerDraw = RecognizerConfig{}.draws.lookalike_pairs_per_draw;  // 4
constexpr double kApart = 0.5;  // m along x between shifted copies: box L1 1 m or more
const float kLookalikeBox = RecognizerConfig{}.draws.lookalike_box_l1;  // the default

struct Copies {
  test::ToyDatabase toy;
  // One workspace per recognition, kept: a Result's ranking lives in its
  // workspace, and the tests compare two Results.
  std::list<host::AlignedBytes> workspaces;
  explicit Copies(double shift) { REQUIRE(test::make_toy_copies(kCopies, shift, &toy)); }
  Result recognize(float lookalike_box_l1, uint32_t transfer_models = 0) {
    RecognizerConfig cfg;
    cfg.draws.max_trials = kTrials;
    cfg.draws.min_hypotheses = 0;            // no extension
    cfg.draws.stop_miss_probability = 0.0f;  // no stop on evidence
    cfg.focus.focus_models = 0;              // only the draws make poses
    cfg.transfer.transfer_models = transfer_models;
    cfg.draws.lookalike_box_l1 = lookalike_box_l1;
    workspaces.emplace_back();
    Result res = test::recognize_copied_toy(toy, cfg, &workspaces.back());
    REQUIRE(res.status == Status::kOk);
    REQUIRE(res.stats.candidates.spread);
    REQUIRE_FALSE(res.stats.draws.budget_exhausted);
    REQUIRE(res.stats.draws.trials == kTrials);
    return res;
  }
};

}  // namespace

TEST_CASE("look-alike doublets: identical copies pair up, a few poses per draw; shifted copies never") {
  Copies identical(0.0);
  const Result off = identical.recognize(0.0f), on = identical.recognize(kLookalikeBox);
  CHECK(on.stats.draws.hypotheses > off.stats.draws.hypotheses);
  CHECK(on.stats.draws.hypotheses <= off.stats.draws.hypotheses + kPairsPerDraw * kTrials);
  CHECK(on.ranking_count >= off.ranking_count);  // more copies get a pose
  CHECK(on.ranking[0].score >= off.ranking[0].score - 1.0f);

  Copies shifted(kApart);  // the same features, boxes 1 m or more apart: a paired pose would be off
  const Result apart_off = shifted.recognize(0.0f), apart_on = shifted.recognize(kLookalikeBox);
  CHECK(apart_on.stats.draws.hypotheses == apart_off.stats.draws.hypotheses);
  CHECK(apart_on.stats.draws.doublets_passed == apart_off.stats.draws.doublets_passed);
  CHECK(apart_on.ranking[0].score == apart_off.ranking[0].score);
}

TEST_CASE("on spread candidates the first model's final pose is lent to its nearest look-alikes") {
  constexpr uint32_t kLent = 16;  // kFinalLookalikes (refinement.cpp)
  Copies identical(0.0);
  // Copies scoring exactly as the first: each lent copy is refined from the
  // first's refined pose, on the same geometry.
  auto ties = [](const Result& r) {
    uint32_t n = 0;
    for (uint32_t i = 0; i < r.ranking_count; ++i) n += r.ranking[i].score == r.ranking[0].score ? 1u : 0u;
    return n;
  };
  const Result lent = identical.recognize(kLookalikeBox, RecognizerConfig{}.transfer.transfer_models);
  const Result kept = identical.recognize(kLookalikeBox, 0);  // transfer_models = 0: no pose is lent
  CHECK(ties(lent) >= 1u + kLent);
  CHECK(ties(kept) < 1u + kLent);
  CHECK(lent.group_size >= 1u + kLent);  // they are one look-alike group, and not confident
  CHECK_FALSE(lent.confident);
}
