// BRAN's trigger for the focused search (recognize/bran.cpp,
// focused_search.cpp): candidates spread over many look-alikes start it
// even when the draws verified enough poses; candidates that name few models
// leave it out (test_pose_transfer.cpp: the trigger by extended draws).
#include <doctest/doctest.h>

#include "blob/aligned_bytes.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_copies.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kCopies = 40;  // identical copies: a feature's W = 50 candidates name most of them
constexpr uint32_t kAmplePoses = 1u << 20;

struct Copies {
  test::ToyDatabase toy;
  host::AlignedBytes ws;
  explicit Copies(uint32_t copies) { REQUIRE(test::make_toy_copies(copies, 0.0, &toy)); }
  RecognitionStats stats(uint32_t focus_models) {
    RecognizerConfig cfg;
    cfg.draws.min_hypotheses = 0;  // the draws are never extended: only the spread can start the search
    // 40 copies pair every doublet 40 ways, half of them tilted: the work
    // budget is not under test. The poses get ample room; the pair checks
    // fit the 800 draws the case was written for (1 600 spend
    // max_pair_checks before the focused search).
    cfg.draws.max_trials = 800;
    cfg.draws.max_hypotheses = kAmplePoses;
    cfg.focus.focus_models = focus_models;
    Result res = test::recognize_copied_toy(toy, cfg, &ws);
    REQUIRE(res.status == Status::kOk);
    REQUIRE_FALSE(res.stats.draws.budget_exhausted);
    return res.stats;
  }
};

}  // namespace

TEST_CASE("candidates spread over many identical copies start the focused search") {
  Copies copies(kCopies);
  const RecognitionStats plain = copies.stats(0), focused = copies.stats(16);
  // The same draws, then focus_trials more for each of the 16 leading copies.
  CHECK(focused.draws.trials == plain.draws.trials + 16u * FocusParams{}.focus_trials);
  CHECK(focused.draws.hypotheses > plain.draws.hypotheses);
}

TEST_CASE("candidates that name a few models leave the focused search out") {
  Copies copies(3);
  const RecognitionStats plain = copies.stats(0), focused = copies.stats(16);
  CHECK(focused.draws.trials == plain.draws.trials);
  CHECK(focused.draws.hypotheses == plain.draws.hypotheses);
}
