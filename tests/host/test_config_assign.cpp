// A recognizer setting by its key (host/config/config_assign.hpp): `--set`
// of the command line and the experiments, and the target runner's
// KEY=VALUE; and every field of the lists through `--set` into the config.
#include <doctest/doctest.h>

#include <CLI/CLI.hpp>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "config/config_assign.hpp"
#include "config/field_table.hpp"
#include "flags/recognizer_flags.hpp"
#include "spinhash/presets.hpp"
#include "spinhash/scene_fields.h"

using spinhash::RecognizerConfig;
using spinhash::host::assign_config_field;
using spinhash::host::ConfigField;
using spinhash::host::FieldKind;

namespace {

// A value inside the field's range other than its default, as text.
std::string other_value(const ConfigField& f, const RecognizerConfig& c) {
  switch (f.kind) {
    case FieldKind::BOOL: return f.in<bool>(c) ? "0" : "1";
    case FieldKind::U32:
    case FieldKind::U64: {
      const unsigned long long v =
          f.kind == FieldKind::U32 ? f.in<uint32_t>(c) : static_cast<unsigned long long>(f.in<uint64_t>(c));
      return std::to_string(v < static_cast<unsigned long long>(f.hi) ? v + 1 : v - 1);
    }
    case FieldKind::F32: {
      const float v = f.in<float>(c);
      const float w = v + 0.5f <= static_cast<float>(f.hi) ? v + 0.5f : (v + static_cast<float>(f.lo)) / 2.0f;
      char text[32];
      std::snprintf(text, sizeof text, "%.9g", static_cast<double>(w));
      return text;
    }
    case FieldKind::MODE:
    case FieldKind::VEC3D: break;
  }
  return "";
}

bool same_field(const ConfigField& f, const RecognizerConfig& a, const RecognizerConfig& b) {
  switch (f.kind) {
    case FieldKind::BOOL: return f.in<bool>(a) == f.in<bool>(b);
    case FieldKind::U32: return f.in<uint32_t>(a) == f.in<uint32_t>(b);
    case FieldKind::U64: return f.in<uint64_t>(a) == f.in<uint64_t>(b);
    case FieldKind::F32: return std::memcmp(&f.in<float>(a), &f.in<float>(b), sizeof(float)) == 0;
    case FieldKind::MODE: return f.in<spinhash::Mode>(a) == f.in<spinhash::Mode>(b);
    case FieldKind::VEC3D:
      return std::memcmp(&f.in<double[3]>(a), &f.in<double[3]>(b), 3 * sizeof(double)) == 0;
  }
  return false;
}

// `spinhash recognize`'s recognizer options parsed from `args`, as the CLI does.
RecognizerConfig parsed(const std::vector<std::string>& args) {
  RecognizerConfig c;
  CLI::App app;
  spinhash::flags::add_recognizer_flags(&app, &c);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  app.parse(reversed);
  return c;
}

}  // namespace

TEST_CASE("config_assign: numbers and booleans by key or name, within the field's range") {
  RecognizerConfig c;
  std::string error;
  CHECK(assign_config_field("candidates.max_bucket_scan=512", &c, &error));
  CHECK(c.candidates.max_bucket_scan == 512u);
  CHECK(assign_config_field("max_bucket_scan=256", &c, &error));  // its Python name
  CHECK(c.candidates.max_bucket_scan == 256u);
  CHECK(assign_config_field("extract.query_cloud_voxel=0.12", &c, &error));
  CHECK(c.extract.query_cloud_voxel == 0.12f);
  CHECK(assign_config_field("seed=18446744073709551615", &c, &error));
  CHECK(c.seed == 18446744073709551615ull);
  CHECK(assign_config_field("refine.refine_poses=0", &c, &error));
  CHECK_FALSE(c.refine.refine_poses);
  CHECK(assign_config_field("focus.enabled=false", &c, &error));
  CHECK_FALSE(c.focus.enabled);
  CHECK(assign_config_field("transfer_enabled=0", &c, &error));  // a switch's Python name
  CHECK_FALSE(c.transfer.enabled);
  const RecognizerConfig before = c;
  for (const char* bad :
       {"candidates.max_bucket_scan=0", "candidates.max_bucket_scan=-1", "candidates.max_bucket_scan=12x",
        "candidates.top_w=", "candidates.top_w", "draws.sigma=1e9", "draws.sigma=nan", "no_such_field=1",
        "draws.no_such_field=1", "refine.refine_poses=2", "mode=1", "viewpoint=1", "enabled=0",
        "top_w.candidates=5"}) {
    CAPTURE(bad);
    error.clear();
    CHECK_FALSE(assign_config_field(bad, &c, &error));
    CHECK_FALSE(error.empty());
  }
  CHECK(c.candidates.max_bucket_scan == before.candidates.max_bucket_scan);
  CHECK(c.candidates.top_w == before.candidates.top_w);
}

TEST_CASE("config_assign: preset=flight sets the preset's fields") {
  RecognizerConfig c;
  std::string error;
  c.seed = 9;
  CHECK(assign_config_field("preset=flight", &c, &error));
  CHECK(c.max_features == spinhash::kFlightMaxFeatures);
  CHECK(c.extract.query_cloud_voxel == spinhash::kFlightQueryVoxel);
  CHECK(c.seed == 9u);
  CHECK(assign_config_field("preset=full", &c, &error));
  CHECK_FALSE(assign_config_field("preset=fast", &c, &error));
}

TEST_CASE("--set reaches every field of the lists, and only that field") {
  const RecognizerConfig defaults;
  int fields = 0;
  for (const ConfigField& f : spinhash::host::config_fields()) {
    if (f.kind == FieldKind::MODE || f.kind == FieldKind::VEC3D) continue;  // their own flags
    const std::string value = other_value(f, defaults);
    INFO("field ", f.key(), " = ", value);
    for (const std::string& name : {f.key(), f.flat()}) {
      const RecognizerConfig c = parsed({"--set", name + "=" + value});
      CHECK_FALSE(same_field(f, c, defaults));
      for (const ConfigField& g : spinhash::host::config_fields())
        if (&g != &f) CHECK_MESSAGE(same_field(g, c, defaults), g.key(), " moved too");
    }
    ++fields;
  }
  CHECK(fields > 100);
}

TEST_CASE("--set applies after the flags and --preset, in order") {
  const RecognizerConfig c = parsed(
      {"--preset", "flight", "--trials", "300", "--set", "draws.max_trials=400", "--set", "max_trials=500"});
  CHECK(c.draws.max_trials == 500u);
  CHECK(c.candidates.top_w == spinhash::kFlightTopW);
  CHECK(parsed({"--set", "candidates.top_w=7", "-W", "9"}).candidates.top_w == 7u);
  CHECK_THROWS(parsed({"--set", "candidates.top_w=0"}));
  CHECK_THROWS(parsed({"--set", "draws.nothing=1"}));
}

TEST_CASE("field names: keys and Python names are unique and none is a scene setting") {
  std::set<std::string> keys, names;
  for (const ConfigField& f : spinhash::host::config_fields()) {
    CHECK_MESSAGE(keys.insert(f.key()).second, "two fields with the key ", f.key());
    CHECK_MESSAGE(names.insert(f.flat()).second, "two fields with the Python name ", f.flat());
  }
  // Python's SceneRecognizer takes the scene's settings and the recognizer's as keywords alike.
#define SPINHASH_SCENE_NAME(kind, name, lo, hi, flag, help) CHECK(names.count(#name) == 0u);
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_SCENE_NAME)
#undef SPINHASH_SCENE_NAME
}
