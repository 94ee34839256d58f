// The named configurations of spinhash/presets.hpp: valid, the fields they
// name and no other, and a recognition under the flight preset.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/presets.hpp"
#include "spinhash/recognizer.hpp"
#include "spinhash/stage_fields.h"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

// The fields two configurations differ in, by key (stage.field for a stage's).
std::vector<std::string> changed_fields(const RecognizerConfig& a, const RecognizerConfig& b) {
  std::vector<std::string> names;
#define SPINHASH_FIELD_CHANGED(kind, name, lo, hi, flag, help) \
  if (std::memcmp(&a.name, &b.name, sizeof a.name) != 0) names.push_back(#name);
  SPINHASH_CONFIG_FIELDS(SPINHASH_FIELD_CHANGED)
#undef SPINHASH_FIELD_CHANGED
#define SPINHASH_PARAM_CHANGED(kind, name, def, lo, hi, flag, why) \
  if (std::memcmp(&pa.name, &pb.name, sizeof pa.name) != 0) names.push_back(std::string(stage) + "." #name);
#define SPINHASH_STAGE_CHANGED(id, Name, what)   \
  {                                              \
    const char* stage = #id;                     \
    const Name##Params &pa = a.id, &pb = b.id;   \
    SPINHASH_PARAMS_##id(SPINHASH_PARAM_CHANGED) \
  }
  SPINHASH_STAGES(SPINHASH_STAGE_CHANGED)
#undef SPINHASH_STAGE_CHANGED
#undef SPINHASH_PARAM_CHANGED
  return names;
}

}  // namespace

TEST_CASE(
    "presets: default is RecognizerConfig{} (the cascade), full its full pass alone, flight its first") {
  CHECK(changed_fields(preset_config(Preset::kDefault), RecognizerConfig{}).empty());
  CHECK(RecognizerConfig{}.cascade);
  CHECK(changed_fields(preset_config(Preset::kFull), RecognizerConfig{}) ==
        std::vector<std::string>{"cascade"});
  const RecognizerConfig flight = preset_config(Preset::kFlight);
  const std::vector<std::string> expected = {"max_features",
                                             "cascade",
                                             "extract.query_cloud_voxel",
                                             "candidates.top_w",
                                             "candidates.max_bucket_scan",
                                             "draws.verify_features",
                                             "draws.max_trials",
                                             "confidence.min_margin"};
  CHECK(changed_fields(flight, RecognizerConfig{}) == expected);
  CHECK(flight.confidence.min_margin == kFirstPassMinMargin);
  CHECK(flight.draws.max_trials == kFlightMaxTrials);
  CHECK(flight.extract.query_cloud_voxel == kFlightQueryVoxel);
  CHECK(flight.max_features == kFlightMaxFeatures);
  CHECK(flight.candidates.max_bucket_scan == kFlightMaxBucketScan);
  CHECK(flight.candidates.top_w == kFlightTopW);
  CHECK(flight.draws.verify_features == kFlightVerifyFeatures);
  // Valid, and a smaller workspace than the default (fewer features).
  CHECK(required_workspace_bytes(flight) > 0);
  CHECK(required_workspace_bytes(flight) < required_workspace_bytes(RecognizerConfig{}));
  // Applied over other settings, it keeps the fields it does not name.
  RecognizerConfig c;
  c.seed = 7;
  c.mode = Mode::kSran;
  apply_preset(Preset::kFlight, &c);
  CHECK(c.seed == 7);
  CHECK(c.mode == Mode::kSran);
  CHECK(c.max_features == kFlightMaxFeatures);
}

TEST_CASE("presets: names") {
  for (Preset p : {Preset::kDefault, Preset::kFlight, Preset::kFull}) {
    Preset back = Preset::kDefault;
    CHECK(preset_from_name(preset_name(p), &back));
    CHECK(back == p);
  }
  Preset untouched = Preset::kFlight;
  CHECK_FALSE(preset_from_name("fast", &untouched));
  CHECK(untouched == Preset::kFlight);
}

TEST_CASE("presets: the flight preset recognises a toy model from its view") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const RecognizerConfig cfg = preset_config(Preset::kFlight);
  host::AlignedBytes workspace(required_workspace_bytes(cfg));
  Recognizer recognizer;
  REQUIRE(recognizer.init(&toy.db, cfg, workspace.data(), workspace.size()) == Status::kOk);
  const uint32_t m = 1;
  const double t[3] = {431000.5, 4020000.25, 87.0};
  const std::vector<double> q = test::toy_query(test::toy_vehicle_points(m, 0.05f), 0.4 + m, t, 0.03, m + 1);
  const Result r = recognizer.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
  REQUIRE(r.status == Status::kOk);
  REQUIRE(r.ranking_count >= 1);
  CHECK(r.ranking[0].model == m);
  CHECK(r.stats.extract.features <= kFlightMaxFeatures);
}
