// The C99 API (spinhash.h) on every target: config and status mirrors, the
// golden blob opened and recognised through it, argument checks, the log hook.
#include <doctest/doctest.h>

#include <cstring>
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "c_api/config_bridge.hpp"
#include "golden/golden_expected.hpp"
#include "spinhash/recognizer.hpp"
#include "spinhash/spinhash.h"
#include "support/golden_files.hpp"

using namespace spinhash;

namespace {

int g_log_calls = 0;
int g_log_level = 0;
std::string g_log_message;

void record_log(int level, const char* message) {
  ++g_log_calls;
  g_log_level = level;
  g_log_message = message;
}

spinhash_config golden_c_config() {
  spinhash_config c;
  to_c_config(golden::golden_config(Mode::kBran), &c);
  return c;
}

}  // namespace

TEST_CASE("C API: the default config and workspace size equal the C++ ones") {
  spinhash_config c;
  spinhash_default_config(&c);
  RecognizerConfig back;
  back.seed = 99;
  REQUIRE(from_c_config(c, &back));
  CHECK(back.seed == RecognizerConfig{}.seed);
  CHECK(spinhash_workspace_bytes(&c) == required_workspace_bytes(RecognizerConfig{}));
  c.max_points = 20000;
  back.max_points = 20000;
  CHECK(spinhash_workspace_bytes(&c) == required_workspace_bytes(back));
  c.mode = 7;  // no such mode
  CHECK(spinhash_workspace_bytes(&c) == 0u);
  CHECK(spinhash_workspace_bytes(nullptr) == 0u);
}

TEST_CASE("C API: status names come from the core for every value") {
  for (int32_t v = -1; v < 64; ++v)
    CHECK(std::strcmp(spinhash_status_name(v), status_name(static_cast<Status>(v))) == 0);
  CHECK(std::strcmp(spinhash_status_name(SPINHASH_BLOB_UNKNOWN_SECTION), "blob section id unknown") == 0);
}

TEST_CASE("C API: the golden blob opens, recognises in float and double, and names its models") {
  host::AlignedBytes blob = test::golden_blob(true);
  spinhash_database db;
  REQUIRE(spinhash_database_open(&db, blob.data(), blob.size()) == SPINHASH_OK);
  CHECK(spinhash_database_model_count(&db) == 6u);
  CHECK(std::strcmp(spinhash_database_model_name(&db, 0), "toy-0") == 0);
  CHECK(spinhash_database_model_name(&db, 6) == nullptr);

  const spinhash_config cfg = golden_c_config();
  host::AlignedBytes workspace(spinhash_workspace_bytes(&cfg));
  spinhash_recognizer rec;
  REQUIRE(spinhash_recognizer_init(&rec, &db, &cfg, workspace.data(), workspace.size()) == SPINHASH_OK);

  const golden::GoldenQuery& want = golden::kGoldenQueries[0];
  const std::vector<float> xyz = test::golden_query_points();
  std::vector<float> f(xyz.begin() + 3 * want.first_point,
                       xyz.begin() + 3 * (want.first_point + want.point_count));
  std::vector<double> d(f.begin(), f.end());
  spinhash_result r32, r64;
  REQUIRE(spinhash_recognize_f32(&rec, f.data(), want.point_count, &r32) == SPINHASH_OK);
  spinhash_ranked_model best32;
  REQUIRE(spinhash_result_entry(&r32, 0, &best32) == SPINHASH_OK);
  REQUIRE(spinhash_recognize_f64(&rec, d.data(), want.point_count, &r64) == SPINHASH_OK);
  spinhash_ranked_model best64;
  REQUIRE(spinhash_result_entry(&r64, 0, &best64) == SPINHASH_OK);

  CHECK(r32.ranking_count == want.ranking_count);
  CHECK(r32.group_size >= 1u);
  CHECK(r32.group_size <= r32.ranking_count);
  CHECK(r64.group_size == r32.group_size);
  CHECK(r32.stats.hypotheses == want.hypotheses);
  CHECK(r32.stats.budget_exhausted == (want.budget_exhausted ? 1u : 0u));
  CHECK(best32.model == want.ranking[0].model);
  CHECK(best64.model == best32.model);
  CHECK(best64.score == best32.score);  // the same floats, read as double
  CHECK(std::strcmp(best32.name, "toy-0") == 0);
  CHECK(best32.has_pose == 1u);
  CHECK(best32.pose[15] == 1.0);
  CHECK(best32.pose[12] == 0.0);
  CHECK(best32.pose[3] == doctest::Approx(want.pose[9]).epsilon(1e-6));
  CHECK(best32.pose[0] == doctest::Approx(want.pose[0]).epsilon(1e-5));
  spinhash_ranked_model past;
  CHECK(spinhash_result_entry(&r64, r64.ranking_count, &past) == SPINHASH_INVALID_ARGUMENT);

  // The class level: toy-0 is a sedan (toy_class), and so the first class.
  CHECK(spinhash_database_model_class(&db, 0) == 1u);
  CHECK(std::strcmp(spinhash_class_name(spinhash_database_model_class(&db, 0)), "sedan") == 0);
  CHECK(spinhash_database_model_class(&db, 6) == SPINHASH_CLASS_COUNT);
  CHECK(spinhash_database_model_group(&db, 0) == 1u);  // a sedan's: light
  CHECK(spinhash_database_model_group(&db, 6) == SPINHASH_GROUP_COUNT);
  CHECK(std::strcmp(spinhash_class_name(SPINHASH_CLASS_COUNT), "unknown") == 0);
  CHECK(std::strcmp(spinhash_group_name(spinhash_class_group(1u)), "light") == 0);     // a sedan
  CHECK(std::strcmp(spinhash_group_name(spinhash_class_group(6u)), "armoured") == 0);  // tracked
  CHECK(spinhash_class_group(SPINHASH_CLASS_COUNT) == 0u);
  CHECK(std::strcmp(spinhash_group_name(SPINHASH_GROUP_COUNT), "unknown") == 0);
  REQUIRE(r32.class_ranking_count >= 2u);
  CHECK(r32.class_ranking_count <= SPINHASH_CLASS_COUNT);
  CHECK(r64.class_confident == r32.class_confident);
  spinhash_ranked_class first, second, beyond;
  REQUIRE(spinhash_result_class(&r32, 0, &first) == SPINHASH_OK);
  REQUIRE(spinhash_result_class(&r32, 1, &second) == SPINHASH_OK);
  CHECK(std::strcmp(first.name, "sedan") == 0);
  CHECK(first.model == best32.model);
  CHECK(first.score == best32.score);
  CHECK(second.score <= first.score);
  CHECK(second.vehicle_class != first.vehicle_class);
  CHECK(spinhash_result_class(&r32, r32.class_ranking_count, &beyond) == SPINHASH_INVALID_ARGUMENT);
  CHECK(spinhash_result_class(&r32, 0, nullptr) == SPINHASH_INVALID_ARGUMENT);
  CHECK(spinhash_result_class(nullptr, 0, &beyond) == SPINHASH_INVALID_ARGUMENT);

  // The answer levels: the model and class flags are the levels', the level
  // is a name of answer_levels.h, the first group is the first class's.
  CHECK(r32.level_confident[SPINHASH_CALIBRATED_LEVELS - 1] == r32.confident);
  CHECK(r32.level_confident[SPINHASH_CALIBRATED_LEVELS - 2] == r32.class_confident);
  CHECK(r32.level < SPINHASH_ANSWER_LEVEL_COUNT);
  CHECK(r64.level == r32.level);
  CHECK(std::strcmp(spinhash_level_name(0u), "none") == 0);
  CHECK(std::strcmp(spinhash_level_name(4u), "model") == 0);
  CHECK(std::strcmp(spinhash_level_name(SPINHASH_ANSWER_LEVEL_COUNT), "unknown") == 0);
  REQUIRE(r32.group_ranking_count >= 1u);
  CHECK(r32.group_ranking_count <= SPINHASH_GROUP_COUNT);
  spinhash_ranked_group group = {0u, 0.0f, 0u, ""}, no_group;
  REQUIRE(spinhash_result_group(&r32, 0, &group) == SPINHASH_OK);
  CHECK(std::strcmp(group.name, "light") == 0);
  CHECK(group.group == spinhash_class_group(first.vehicle_class));
  CHECK(group.score == first.score);
  CHECK(spinhash_result_group(&r32, r32.group_ranking_count, &no_group) == SPINHASH_INVALID_ARGUMENT);
  CHECK(spinhash_result_group(&r32, 0, nullptr) == SPINHASH_INVALID_ARGUMENT);
}

TEST_CASE("C API: bad arguments are statuses, never crashes") {
  spinhash_database db;
  CHECK(spinhash_database_open(nullptr, nullptr, 0) == SPINHASH_INVALID_ARGUMENT);
  CHECK(spinhash_database_open(&db, nullptr, 0) == SPINHASH_INVALID_ARGUMENT);
  CHECK(spinhash_database_model_count(&db) == 0u);
  CHECK(spinhash_database_model_name(nullptr, 0) == nullptr);

  spinhash_recognizer rec;
  spinhash_config cfg = golden_c_config();
  alignas(SPINHASH_BUFFER_ALIGNMENT) static unsigned char small[256];
  CHECK(spinhash_recognizer_init(&rec, &db, &cfg, small, sizeof small) ==
        SPINHASH_INVALID_ARGUMENT);  // db not open
  spinhash_result r;
  const float p[3] = {0, 0, 0};
  CHECK(spinhash_recognize_f32(&rec, p, 1, &r) == SPINHASH_NOT_OPEN);
  CHECK(r.status == SPINHASH_NOT_OPEN);
  CHECK(spinhash_recognize_f32(&rec, p, 1, nullptr) == SPINHASH_INVALID_ARGUMENT);
  CHECK(spinhash_result_entry(&r, 0, nullptr) == SPINHASH_INVALID_ARGUMENT);
  CHECK(spinhash_recognizer_init(nullptr, &db, &cfg, small, sizeof small) == SPINHASH_INVALID_ARGUMENT);

  host::AlignedBytes blob = test::golden_blob(true);
  REQUIRE(spinhash_database_open(&db, blob.data(), blob.size()) == SPINHASH_OK);
  CHECK(spinhash_recognizer_init(&rec, &db, &cfg, small, sizeof small) == SPINHASH_WORKSPACE_TOO_SMALL);
  CHECK(spinhash_recognizer_init(&rec, &db, nullptr, small, sizeof small) == SPINHASH_INVALID_ARGUMENT);
}

TEST_CASE("C API: a failed open goes to the log hook; no hook, no call") {
  host::AlignedBytes other = test::golden_blob(false);
  spinhash_database db;
  g_log_calls = 0;
  spinhash_set_log_hook(record_log);
  CHECK(spinhash_database_open(&db, other.data(), other.size()) == SPINHASH_BLOB_WRONG_BYTE_ORDER);
  spinhash_set_log_hook(nullptr);
  CHECK(spinhash_database_open(&db, other.data(), other.size()) == SPINHASH_BLOB_WRONG_BYTE_ORDER);
  CHECK(g_log_calls == 1);
  CHECK(g_log_level == SPINHASH_LOG_ERROR);
#ifndef SPINHASH_NO_LOG_STRINGS
  CHECK(g_log_message == "database open: blob written for the other byte order");
#endif
}
