// The cascade (RecognizerConfig::cascade, recognizer.cpp): a clear view is
// answered by the first pass alone; an unsure one goes on to the full pass,
// which is the full preset's own pass (plus, with carry.enabled, the first
// pass's carried poses);
// the work cap stops a query with its best answer so far; the first pass's
// answer ends the query when its own calibrated table flags it.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_writer.hpp"
#include "recognize/work_meter.hpp"
#include "spinhash/presets.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

struct Run {
  Result result;
  std::vector<uint32_t> models;
  std::vector<float> scores;
  std::vector<bool> posed;
  std::vector<uint32_t> classes;  // the class ranking's
};

// Recognises toy model `m`'s noisy view (from the side, or with `airborne`
// its whole top) under `cfg`; the ranking copied out of the workspace.
Run recognize_toy(const test::ToyDatabase& toy, const RecognizerConfig& cfg, uint32_t m,
                  bool airborne = false) {
  host::AlignedBytes workspace(required_workspace_bytes(cfg));
  Recognizer recognizer;
  REQUIRE(recognizer.init(&toy.db, cfg, workspace.data(), workspace.size()) == Status::kOk);
  const double t[3] = {431000.5, 4020000.25, 87.0};
  const std::vector<double> model = test::toy_vehicle_points(m, 0.05f);
  const std::vector<double> q = airborne ? test::toy_airborne_query(model, 0.4 + m, t, 0.03, m + 1)
                                         : test::toy_query(model, 0.4 + m, t, 0.03, m + 1);
  Run run;
  run.result = recognizer.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
  for (uint32_t i = 0; i < run.result.ranking_count; ++i) {
    run.models.push_back(run.result.ranking[i].model);
    run.scores.push_back(run.result.ranking[i].score);
    run.posed.push_back(run.result.ranking[i].has_pose);
  }
  for (uint32_t i = 0; i < run.result.class_ranking_count; ++i)
    run.classes.push_back(run.result.class_ranking[i].vehicle_class);
  // The rankings live in the workspace, which ends here: read the copies.
  run.result.ranking = nullptr;
  run.result.class_ranking = nullptr;
  run.result.group_ranking = nullptr;
  return run;
}

}  // namespace

TEST_CASE("cascade: a clear view is answered confidently by the first pass alone, as the flight preset") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const uint32_t m = 1;
  const Run cascade = recognize_toy(toy, RecognizerConfig{}, m, true);
  REQUIRE(cascade.result.status == Status::kOk);
  REQUIRE(cascade.result.ranking_count >= 1);
  if (!cascade.models.empty()) CHECK(cascade.models[0] == m);
  CHECK(cascade.result.confident);
  const CascadeStats& c = cascade.result.stats.cascade;
  CHECK(c.passes == 1u);
  CHECK(c.answered_by == 0u);
  CHECK(c.first_work > 0u);
  CHECK(c.full_work == 0u);
  CHECK(c.work == c.first_work);
  CHECK(cascade.result.stats.extract.features <= kFlightMaxFeatures);
  // The first pass is the flight preset's recognition, answer for answer.
  const Run flight = recognize_toy(toy, preset_config(Preset::kFlight), m, true);
  CHECK(flight.models == cascade.models);
  CHECK(flight.scores == cascade.scores);
  CHECK(flight.result.confident == cascade.result.confident);
  CHECK(flight.result.stats.cascade.passes == 1u);
  CHECK(flight.result.stats.cascade.answered_by == 1u);  // a single pass is the configured one
}

TEST_CASE("cascade: an unsure first pass goes on to the full pass, which starts from its poses") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const uint32_t m = 2;
  // A side view: the first pass's few coarse features do not make it sure.
  RecognizerConfig carried;
  carried.carry.enabled = true;
  const Run escalated = recognize_toy(toy, carried, m);
  REQUIRE(escalated.result.status == Status::kOk);
  REQUIRE(escalated.result.ranking_count >= 1);
  if (!escalated.models.empty()) CHECK(escalated.models[0] == m);
  const CascadeStats& c = escalated.result.stats.cascade;
  CHECK(c.passes == 2u);
  CHECK(c.answered_by == 1u);
  CHECK(c.first_work > 0u);
  CHECK(c.full_work > c.first_work);  // the full pass describes more, finer features
  CHECK(c.work == c.first_work + c.full_work);
  CHECK(escalated.result.stats.carry.carried > 0u);
  CHECK(escalated.result.stats.extract.features > kFlightMaxFeatures);

  // Without the carried poses, the full pass is the full preset's: the
  // shared workspace carries nothing else from the first pass.
  const Run plain = recognize_toy(toy, RecognizerConfig{}, m);  // carrying is off by default
  const Run full = recognize_toy(toy, preset_config(Preset::kFull), m);
  REQUIRE(plain.result.stats.cascade.passes == 2u);
  CHECK(plain.result.stats.carry.carried == 0u);
  CHECK(full.result.stats.cascade.passes == 1u);
  CHECK(full.result.stats.cascade.first_work == 0u);
  CHECK(full.result.stats.cascade.full_work == full.result.stats.cascade.work);
  CHECK(plain.models == full.models);
  CHECK(plain.scores == full.scores);
  CHECK(plain.result.confident == full.result.confident);
  CHECK(plain.result.stats.cascade.full_work == full.result.stats.cascade.work);
}

TEST_CASE("cascade: the work cap ends a query with its best answer so far, never confident") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const uint32_t m = 4;  // the toy van: the cheapest airborne view to search whole
  RecognizerConfig full = preset_config(Preset::kFull);
  // An airborne view: the whole search flags it (a half view has no level:
  // no model's box fits it).
  const Run whole = recognize_toy(toy, full, m, true);
  REQUIRE(whole.result.status == Status::kOk);
  const uint64_t work = whole.result.stats.cascade.work;
  REQUIRE(work > 0u);
  REQUIRE_FALSE(whole.result.stats.cascade.work_capped);
  // A cap past the extraction and the candidates, in the draws.
  const ExtractStats& e = whole.result.stats.extract;
  const uint64_t described =
      kWorkPerPoint * e.points_equalised + kWorkPerBucketEntry * whole.result.stats.candidates.bucket_entries;
  REQUIRE(described < work);
  full.max_work = described + (work - described) / 4u;
  const Run capped = recognize_toy(toy, full, m, true);
  CHECK(capped.result.status == Status::kWorkCapReached);
  CHECK(capped.result.stats.cascade.work_capped);
  CHECK(capped.result.stats.cascade.work >= full.max_work);
  CHECK(capped.result.stats.cascade.work < work);
  CHECK(capped.result.stats.draws.budget_exhausted);
  CHECK_FALSE(capped.result.confident);
  CHECK_FALSE(capped.result.class_confident);
  // No level is flagged either, the coarse ones included, though the whole
  // search flags one.
  CHECK(whole.result.level != AnswerLevel::kNone);
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) CHECK_FALSE(capped.result.levels[l].confident);
  CHECK(capped.result.level == AnswerLevel::kNone);
  REQUIRE(capped.result.ranking_count >= 1);  // the best answer so far
  // An escalated query whose full pass reaches the cap after its
  // extraction, before its draws, still verifies the first pass's poses on
  // the full pass's features and answers with them.
  {
    RecognizerConfig cascade;
    cascade.carry.enabled = true;
    const Run side = recognize_toy(toy, cascade, 2u);
    REQUIRE(side.result.stats.cascade.passes == 2u);
    REQUIRE(side.result.stats.cascade.answered_by == 1u);  // the stage blocks are the full pass's
    const uint64_t extraction = kWorkPerPoint * side.result.stats.extract.points_equalised;
    cascade.max_work = side.result.stats.cascade.first_work + extraction + 1u;
    const Run early = recognize_toy(toy, cascade, 2u);
    CHECK(early.result.status == Status::kWorkCapReached);
    CHECK(early.result.stats.cascade.passes == 2u);
    CHECK(early.result.stats.draws.trials == 0u);
    CHECK(early.result.stats.carry.carried > 0u);
    REQUIRE(early.result.ranking_count >= 1u);
    if (!early.models.empty()) CHECK(early.models[0] == 2u);
    CHECK_FALSE(early.result.confident);
  }
  // The cascade's first pass counts against the same cap: spent there, the
  // full pass never starts.
  RecognizerConfig tight;
  tight.first_min_margin = 1e6f;
  tight.max_work = 1;
  const Run first = recognize_toy(toy, tight, m);
  CHECK(first.result.status == Status::kWorkCapReached);
  CHECK(first.result.stats.cascade.passes == 1u);
  CHECK(first.result.stats.cascade.answered_by == 0u);
  CHECK(first.result.ranking_count == 0u);
}

// A full pass the cap stops before its first hypothesis, without carried
// poses, names no posed model: the query answers with the first pass's
// leading models, still capped and unflagged, its stats those of both passes.
TEST_CASE("cascade: a full pass capped before it poses a model answers with the first pass's models") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  RecognizerConfig cascade;  // carrying off, the default
  const Run side = recognize_toy(toy, cascade, 2u);
  REQUIRE(side.result.stats.cascade.passes == 2u);
  const Run flight = recognize_toy(toy, preset_config(Preset::kFlight), 2u);  // the first pass alone
  REQUIRE(flight.result.ranking_count >= 1u);
  REQUIRE(flight.posed[0]);
  cascade.max_work = side.result.stats.cascade.first_work + 1u;
  const Run early = recognize_toy(toy, cascade, 2u);
  CHECK(early.result.status == Status::kWorkCapReached);
  // The answer's stage counts are the first pass's.
  CHECK(early.result.stats.draws.trials == flight.result.stats.draws.trials);
  CHECK(early.result.stats.carry.carried == 0u);
  const CascadeStats& c = early.result.stats.cascade;
  CHECK(c.passes == 2u);
  CHECK(c.answered_by == 0u);
  CHECK(c.work_capped);
  CHECK(c.first_work == flight.result.stats.cascade.work);
  CHECK(c.full_work > 0u);
  CHECK(c.work == c.first_work + c.full_work);
  REQUIRE(early.result.ranking_count >= 1u);
  if (early.models.empty()) return;  // REQUIRE does not end the test without exceptions
  CHECK(early.posed[0]);
  CHECK(early.models[0] == flight.models[0]);
  CHECK(early.scores[0] == flight.scores[0]);
  const size_t kept = early.models.size();
  REQUIRE(kept == (flight.models.size() < kMaxCarriedPoses ? flight.models.size() : kMaxCarriedPoses));
  if (kept > flight.models.size()) return;
  CHECK(std::vector<uint32_t>(flight.models.begin(), flight.models.begin() + kept) == early.models);
  CHECK_FALSE(early.result.confident);
  CHECK_FALSE(early.result.class_confident);
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) CHECK_FALSE(early.result.levels[l].confident);
  CHECK(early.result.level == AnswerLevel::kNone);
  REQUIRE_FALSE(early.classes.empty());
  REQUIRE_FALSE(flight.classes.empty());
  if (!early.classes.empty() && !flight.classes.empty()) CHECK(early.classes[0] == flight.classes[0]);
}

namespace {

// A calibrated cell that flags every evidence (`always`), or one that
// flags none.
blob::CalibrationCell calibrated_cell(bool always) {
  blob::CalibrationCell c{};
  if (!always) {
    c.state = blob::kCellUnreachable;
    return c;
  }
  c.state = blob::kCellFitted;
  c.threshold = -1e30f;  // below every finite evidence
  c.precision = 1.0f;
  c.recall = 1.0f;
  c.positives = 1u;
  c.flagged = 1u;
  return c;
}

// The agree table of make_calibrated_toy().
enum class AgreeTable { kAbsent, kNever, kAlways };

// The toy database with a calibration of both passes, one density band:
// the full pass's table flags every level's evidence; the first pass's
// flags every one (`first_flags`) or none; the agree table, when there is
// one, likewise.
bool make_calibrated_toy(test::ToyDatabase* out, bool first_flags, AgreeTable agree = AgreeTable::kNever) {
  host::BlobContent content;
  host::BuildReport report;
  std::string error;
  if (!host::build_database(test::toy_clouds(), host::BuildOptions(), &content, &report, &error))
    return false;
  host::CalibrationContent& c = content.calibration;
  c = host::CalibrationContent{};
  const uint32_t passes = agree == AgreeTable::kAbsent ? 2u : 3u;
  c.header.pass_count = passes;
  c.header.level_count = kCalibratedLevels;
  c.header.band_count = 1;
  c.header.target_precision = 0.99f;
  c.header.scans_per_model = 1;
  for (uint32_t p = 0; p < passes; ++p) {
    const bool is_agree = p == static_cast<uint32_t>(AnswerPass::kAgree);
    c.passes.push_back(blob::CalibrationPass{p, blob::kSourceFitted, 1u, is_agree ? 0.995f : 0.0f});
    const bool flags = p == static_cast<uint32_t>(AnswerPass::kFirst) ? first_flags
                       : is_agree                                     ? agree == AgreeTable::kAlways
                                                                      : true;
    for (uint32_t l = 0; l < kCalibratedLevels; ++l) c.cells.push_back(calibrated_cell(flags));
  }
  std::vector<uint8_t> bytes;
  if (!host::serialize_blob(content, host::ByteOrder::kNative, &bytes, &error)) return false;
  out->bytes = host::AlignedBytes::copy_of(bytes);
  return Database::open(out->bytes.data(), out->bytes.size(), &out->db) == Status::kOk;
}

}  // namespace

TEST_CASE("cascade: the first pass stops the query only when confident by the first pass's own table") {
  const uint32_t m = 1;  // the clear view the priors answer in the first pass
  test::ToyDatabase never_first, always_first;
  REQUIRE(make_calibrated_toy(&never_first, false));
  REQUIRE(make_calibrated_toy(&always_first, true));
  REQUIRE(never_first.db.calibration().fitted(AnswerPass::kFirst));

  // The first pass's table flags nothing: the query goes on to the full
  // pass, whose own table flags its answer.
  const Run escalated = recognize_toy(never_first, RecognizerConfig{}, m, true);
  REQUIRE(escalated.result.status == Status::kOk);
  CHECK(escalated.result.stats.cascade.passes == 2u);
  CHECK(escalated.result.stats.cascade.answered_by == 1u);
  CHECK_FALSE(escalated.result.stats.cascade.stopped_on_agreement);
  CHECK(escalated.result.confident);

  // The first pass's table flags its answer: the query ends there.
  const Run stopped = recognize_toy(always_first, RecognizerConfig{}, m, true);
  REQUIRE(stopped.result.status == Status::kOk);
  CHECK(stopped.result.stats.cascade.passes == 1u);
  CHECK(stopped.result.stats.cascade.answered_by == 0u);
  CHECK_FALSE(stopped.result.stats.cascade.stopped_on_agreement);  // confident: the agree table is not asked
  CHECK(stopped.result.confident);

  // The flight preset runs the first pass's settings alone, and its flags
  // are the first pass's table's; the full preset's the full pass's.
  CHECK(calibration_pass(preset_config(Preset::kFlight)) == AnswerPass::kFirst);
  CHECK(calibration_pass(preset_config(Preset::kFull)) == AnswerPass::kFull);
  CHECK_FALSE(recognize_toy(never_first, preset_config(Preset::kFlight), m, true).result.confident);
  CHECK(recognize_toy(never_first, preset_config(Preset::kFull), m, true).result.confident);
}

TEST_CASE("cascade: the agree table stops an unsure first pass; its flags stay the first pass's own") {
  const uint32_t m = 1;
  test::ToyDatabase agrees, never_agrees, no_agree_table;
  REQUIRE(make_calibrated_toy(&agrees, false, AgreeTable::kAlways));
  REQUIRE(make_calibrated_toy(&never_agrees, false, AgreeTable::kNever));
  REQUIRE(make_calibrated_toy(&no_agree_table, false, AgreeTable::kAbsent));
  REQUIRE(agrees.db.calibration().fitted(AnswerPass::kAgree));
  REQUIRE_FALSE(no_agree_table.db.calibration().fitted(AnswerPass::kAgree));

  // The first pass is not confident by its table, but stopping loses no
  // right answer: the query ends after the first pass, unflagged.
  const Run stopped = recognize_toy(agrees, RecognizerConfig{}, m, true);
  REQUIRE(stopped.result.status == Status::kOk);
  const CascadeStats& c = stopped.result.stats.cascade;
  CHECK(c.passes == 1u);
  CHECK(c.answered_by == 0u);
  CHECK(c.stopped_on_agreement);
  CHECK(c.full_work == 0u);
  CHECK_FALSE(stopped.result.confident);
  CHECK_FALSE(stopped.result.class_confident);
  CHECK(stopped.result.level == AnswerLevel::kNone);
  // Its answer is the first pass's: the flight preset's ranking.
  const Run flight = recognize_toy(agrees, preset_config(Preset::kFlight), m, true);
  CHECK(flight.models == stopped.models);
  CHECK(flight.scores == stopped.scores);

  // An agree table that never agrees, or none (the first pass's flag
  // decides alone): on to the full pass.
  for (const test::ToyDatabase* db : {&never_agrees, &no_agree_table}) {
    const Run escalated = recognize_toy(*db, RecognizerConfig{}, m, true);
    REQUIRE(escalated.result.status == Status::kOk);
    CHECK(escalated.result.stats.cascade.passes == 2u);
    CHECK(escalated.result.stats.cascade.answered_by == 1u);
    CHECK_FALSE(escalated.result.stats.cascade.stopped_on_agreement);
    CHECK(escalated.result.confident);
  }
}

TEST_CASE(
    "cascade: a caller's work cap below max_work ends a query as max_work would; lifted, it answers in "
    "full") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const RecognizerConfig full = preset_config(Preset::kFull);
  host::AlignedBytes workspace(required_workspace_bytes(full));
  Recognizer recognizer;
  REQUIRE(recognizer.init(&toy.db, full, workspace.data(), workspace.size()) == Status::kOk);
  const double t[3] = {431000.5, 4020000.25, 87.0};
  const std::vector<double> q = test::toy_query(test::toy_vehicle_points(3, 0.05f), 3.4, t, 0.03, 4);
  const uint32_t n = static_cast<uint32_t>(q.size() / 3);
  const Result whole = recognizer.recognize(q.data(), n);
  REQUIRE(whole.status == Status::kOk);
  const uint64_t work = whole.stats.cascade.work;
  recognizer.set_work_cap(work / 2u);
  const Result half = recognizer.recognize(q.data(), n);
  CHECK(half.status == Status::kWorkCapReached);
  CHECK(half.stats.cascade.work_capped);
  CHECK(half.stats.cascade.work >= work / 2u);
  CHECK(half.stats.cascade.work < work);
  CHECK_FALSE(half.confident);
  recognizer.set_work_cap(Recognizer::kNoWorkCap);
  const Result again = recognizer.recognize(q.data(), n);
  CHECK(again.status == Status::kOk);
  CHECK(again.stats.cascade.work == work);
  REQUIRE(again.ranking_count >= 1u);
  REQUIRE(whole.ranking_count >= 1u);
  CHECK(again.ranking[0].model == whole.ranking[0].model);
  CHECK(again.ranking[0].score == whole.ranking[0].score);
}

// The cap bounds a query by its configuration, not by its cloud: the
// extraction's charge is known before its normals and spin images, and the
// candidates stop after the feature whose bucket scan reaches the cap.
TEST_CASE("cascade: the work cap stops the extraction and the candidates before they pass it") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const uint32_t m = 4;
  RecognizerConfig full = preset_config(Preset::kFull);
  const Run whole = recognize_toy(toy, full, m, true);
  REQUIRE(whole.result.status == Status::kOk);
  const ExtractStats& e = whole.result.stats.extract;
  const uint64_t extraction = kWorkPerPoint * e.points_equalised;
  const uint64_t entries = whole.result.stats.candidates.bucket_entries;
  REQUIRE(e.features > 2u);
  REQUIRE(entries > 0u);

  SUBCASE("a cap the extraction would reach: charged, not run") {
    full.max_work = extraction;  // exactly its charge
    const Run capped = recognize_toy(toy, full, m, true);
    CHECK(capped.result.status == Status::kWorkCapReached);
    CHECK(capped.result.stats.extract.points_equalised == e.points_equalised);  // equalised, then stopped
    CHECK(capped.result.stats.extract.points_oriented == 0u);
    CHECK(capped.result.stats.extract.features == 0u);
    CHECK(capped.result.stats.candidates.bucket_entries == 0u);
    CHECK(capped.result.stats.cascade.work == extraction);
    CHECK(capped.result.ranking_count == 0u);  // nothing was posed
    CHECK_FALSE(capped.result.confident);
    CHECK(capped.result.level == AnswerLevel::kNone);
  }
  SUBCASE("one unit more: the extraction runs, the candidates stop at once") {
    full.max_work = extraction + 1u;
    const Run capped = recognize_toy(toy, full, m, true);
    CHECK(capped.result.status == Status::kWorkCapReached);
    CHECK(capped.result.stats.extract.features == e.features);
    const uint64_t scanned = capped.result.stats.candidates.bucket_entries;
    CHECK(scanned > 0u);
    CHECK(scanned < entries);
    CHECK(capped.result.stats.candidates.salient_features <= 1u);  // the first feature's scan alone
    CHECK(capped.result.stats.draws.trials == 0u);
    CHECK(capped.result.ranking_count == 0u);
  }
  SUBCASE("a cap halfway through the candidates: passed by at most one feature's scan") {
    full.max_work = extraction + entries / 2u;
    const Run capped = recognize_toy(toy, full, m, true);
    CHECK(capped.result.status == Status::kWorkCapReached);
    const uint64_t scanned = capped.result.stats.candidates.bucket_entries;
    CHECK(scanned >= entries / 2u);
    CHECK(scanned < entries);
    CHECK(capped.result.stats.candidates.salient_features < whole.result.stats.candidates.salient_features);
    CHECK(capped.result.stats.draws.trials == 0u);
    // The scan stops after the feature that reaches the cap: a cap at what
    // it scanned stops there again, one entry more takes one feature more.
    full.max_work = extraction + scanned;
    CHECK(recognize_toy(toy, full, m, true).result.stats.candidates.bucket_entries == scanned);
    full.max_work = extraction + scanned + 1u;
    CHECK(recognize_toy(toy, full, m, true).result.stats.candidates.bucket_entries > scanned);
  }
}

// The refine stage checks the cap before each leader's rescoring and each
// refinement, and its lending before each round and each look-alike: a query
// capped there passes its cap by at most one such step, which its settings
// and features bound (work_meter.hpp), its rescorings and screens counted.
TEST_CASE("cascade: the work cap stops the refine stage within one model's rescoring or refinement") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  for (const uint32_t m : {2u, 4u}) {
    INFO("toy model " << m);
    RecognizerConfig full = preset_config(Preset::kFull);
    const Run whole = recognize_toy(toy, full, m, true);
    REQUIRE(whole.result.status == Status::kOk);
    const RecognitionStats& s = whole.result.stats;
    const uint64_t features = s.extract.features;
    const uint64_t subset = full.draws.verify_features < features ? full.draws.verify_features : features;
    // The step between two checks can count at most one look-alike's
    // lending: its end-aligned screens, its rescoring and its refinement.
    const uint64_t bound = kWorkPerVerifiedFeature *
                           ((1u + full.refine.refine_iterations) * features + kEndAlignedPoses * subset);
    CHECK(refine_step_work(features, full) == bound);
    // What the refine stage counts: its rescorings and screens too.
    REQUIRE(s.refine.rescores > 0u);
    REQUIRE(s.refine.refinements > 0u);
    REQUIRE(s.refine.screens > 0u);
    const uint64_t refine_work =
        kWorkPerVerifiedFeature * ((uint64_t{s.refine.rescores} + s.refine.refinements) * features +
                                   uint64_t{s.refine.screens} * subset);
    REQUIRE(refine_work < s.cascade.work);
    const uint64_t before_refine = s.cascade.work - refine_work;
    REQUIRE(refine_work > 2u * bound);  // a cap inside the stage cuts it short

    // One unit into the stage: the first leader alone is rescored, counted,
    // and finalised above the others; nothing is refined or lent.
    full.max_work = before_refine + 1u;
    const Run first = recognize_toy(toy, full, m, true);
    CHECK(first.result.status == Status::kWorkCapReached);
    CHECK(first.result.stats.refine.rescores == 1u);
    CHECK(first.result.stats.refine.refinements == 0u);
    CHECK(first.result.stats.refine.screens == 0u);
    CHECK(first.result.stats.cascade.work == before_refine + kWorkPerVerifiedFeature * features);
    CHECK(first.result.ranking_count == whole.result.ranking_count);
    REQUIRE(first.scores.size() >= 2u);
    CHECK(first.scores[0] > first.scores[1]);
    CHECK_FALSE(first.result.confident);

    // Caps across the stage: each passed by less than one step.
    for (uint64_t k = 1; k < 8; ++k) {
      full.max_work = before_refine + refine_work * k / 8u;
      INFO("cap " << full.max_work);
      const Run capped = recognize_toy(toy, full, m, true);
      CHECK(capped.result.status == Status::kWorkCapReached);
      CHECK(capped.result.stats.cascade.work >= full.max_work);
      CHECK(capped.result.stats.cascade.work < full.max_work + bound);
      CHECK(capped.result.ranking_count == whole.result.ranking_count);
    }

    // A cap the query reaches with its last step: every check passes before
    // it, so the answer is the uncapped one, only its status capped; one
    // unit more and it is the uncapped answer itself.
    full.max_work = s.cascade.work;
    const Run at_end = recognize_toy(toy, full, m, true);
    CHECK(at_end.result.status == Status::kWorkCapReached);
    CHECK(at_end.result.stats.cascade.work == s.cascade.work);
    CHECK(at_end.models == whole.models);
    CHECK(at_end.scores == whole.scores);
    full.max_work = s.cascade.work + 1u;
    const Run past_end = recognize_toy(toy, full, m, true);
    CHECK(past_end.result.status == Status::kOk);
    CHECK(past_end.result.stats.cascade.work == s.cascade.work);
    CHECK(past_end.models == whole.models);
    CHECK(past_end.scores == whole.scores);
    CHECK(past_end.result.confident == whole.result.confident);
  }
}

// The transfer stage checks the cap before each pose it lends: a query
// capped there passes its cap by at most one pose's verification.
TEST_CASE("cascade: the work cap stops the transfer stage within one lent pose") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const uint32_t m = 4;
  RecognizerConfig full = preset_config(Preset::kFull);
  const Run whole = recognize_toy(toy, full, m, true);
  REQUIRE(whole.result.status == Status::kOk);
  const RecognitionStats& s = whole.result.stats;
  const uint64_t features = s.extract.features;
  const uint64_t subset = full.draws.verify_features < features ? full.draws.verify_features : features;
  const uint64_t pose = kWorkPerVerifiedFeature * subset;
  REQUIRE(s.transfer.transferred > 4u);
  // The stages after the transfer (the refine stage; the focused search
  // does not run on this clear view) count what the refine stage keeps.
  const uint64_t after_transfer =
      kWorkPerVerifiedFeature *
      ((uint64_t{s.refine.rescores} + s.refine.refinements) * features + uint64_t{s.refine.screens} * subset);
  const uint64_t before_transfer = s.cascade.work - after_transfer - pose * s.transfer.transferred;
  full.max_work = before_transfer + 1u;  // the first lent pose reaches it
  const Run first = recognize_toy(toy, full, m, true);
  CHECK(first.result.status == Status::kWorkCapReached);
  CHECK(first.result.stats.transfer.transferred == 1u);
  CHECK(first.result.stats.refine.rescores == 0u);
  CHECK(first.result.stats.cascade.work == before_transfer + pose);
  CHECK(first.result.ranking_count >= 1u);
  for (uint64_t k = 1; k < 4; ++k) {
    full.max_work = before_transfer + pose * s.transfer.transferred * k / 4u;
    INFO("cap " << full.max_work);
    const Run capped = recognize_toy(toy, full, m, true);
    CHECK(capped.result.status == Status::kWorkCapReached);
    CHECK(capped.result.stats.cascade.work >= full.max_work);
    CHECK(capped.result.stats.cascade.work < full.max_work + pose);
    CHECK(capped.result.stats.transfer.transferred < s.transfer.transferred);
  }
}
