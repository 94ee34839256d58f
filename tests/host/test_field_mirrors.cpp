// The command line and the documentation against the lists they mirror:
// spinhash/config_fields.h and stage_fields.h (every recognizer field with a
// flag has it in `recognize --help` and in docs/cli.md, every stage's
// fields are its table in docs/api.md, every statistic its JSON key in
// docs/cli.md), spinhash/scene_fields.h (the scene's flags in `scene --help`,
// `survey --help` and docs/cli.md; the settings tables of docs/api.md; the
// keys of `scene`'s lines), spinhash/status_list.h (the status table of
// docs/api.md), and the folders of the tree (README's folder table).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/report_keys.hpp"
#include "cli_runner.hpp"
#include "config/field_table.hpp"
#include "pipeline/level_json.hpp"
#include "spinhash/answer_levels.h"
#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/scene_fields.h"
#include "spinhash/scene_stream.hpp"
#include "spinhash/status.hpp"
#include "spinhash/vehicle_classes.h"

using namespace spinhash;

namespace {

using spinhash::host::test::read_bytes;
using spinhash::host::test::write_bytes;

// "-W,--top-w" -> "--top-w"; "!--no-refine" -> "--no-refine".
std::string long_flag(const std::string& spec) {
  const size_t at = spec.find("--");
  return at == std::string::npos ? spec : spec.substr(at);
}

// The rows of the markdown table whose header's first cell is `first`, as
// trimmed cells (none when there is no such table).
std::vector<std::vector<std::string>> table_rows(const std::string& doc, const std::string& first) {
  std::vector<std::vector<std::string>> rows;
  size_t at = doc.find("\n| " + first + " |");
  if (at == std::string::npos) return rows;
  at = doc.find('\n', at + 1);      // the header
  at = doc.find('\n', at + 1) + 1;  // the rule
  for (size_t end; at < doc.size() && doc[at] == '|' && (end = doc.find('\n', at)) != std::string::npos;
       at = end + 1) {
    std::vector<std::string> cells;
    const std::string line = doc.substr(at + 1, end - at - 1);
    size_t from = 0;
    for (size_t bar; (bar = line.find('|', from)) != std::string::npos; from = bar + 1) {
      std::string cell = line.substr(from, bar - from);
      const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
    }
    rows.push_back(cells);
  }
  return rows;
}

bool near(double doc, double value) {
  return std::fabs(doc - value) <= 1e-6 * std::fmax(1.0, std::fabs(value));
}
double number(const std::string& s) { return s == "inf" ? INFINITY : std::strtod(s.c_str(), nullptr); }

// A default as the table writes it.
bool same_default(const std::string& doc, uint32_t v) { return doc == std::to_string(v); }
bool same_default(const std::string& doc, uint64_t v) { return doc == std::to_string(v); }
bool same_default(const std::string& doc, float v) { return near(number(doc), static_cast<double>(v)); }
bool same_default(const std::string& doc, bool v) { return doc == (v ? "true" : "false"); }
bool same_default(const std::string& doc, const double (&v)[3]) {
  return doc == "0 0 0" && v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

// A range as the table writes it: [lo, hi], ( for a range open at 0
// (kSmallestPositive), ) for one open above (kNoUpperBound); "-" for none.
template <typename L, typename H>
bool same_range(const std::string& doc, L lo, H hi, bool has_range) {
  if (!has_range) return doc == "-";
  const size_t comma = doc.find(", ");
  if (doc.size() < 6 || comma == std::string::npos) return false;
  const double dlo = number(doc.substr(1, comma - 1)),
               dhi = number(doc.substr(comma + 2, doc.size() - comma - 3));
  const bool lo_ok = doc.front() == '(' ? dlo == 0.0 && static_cast<float>(lo) == kSmallestPositive
                                        : doc.front() == '[' && static_cast<float>(lo) != kSmallestPositive &&
                                              near(dlo, static_cast<double>(lo));
  const bool hi_ok = doc.back() == ')' ? std::isinf(dhi) && static_cast<float>(hi) == kNoUpperBound
                                       : doc.back() == ']' && near(dhi, static_cast<double>(hi));
  return lo_ok && hi_ok;
}

constexpr bool ranged_U32 = true, ranged_U64 = true, ranged_F32 = true, ranged_BOOL = false,
               ranged_VEC3D = false;

// The members of a JSON object's outer level, in order.
std::vector<std::string> top_keys(const std::string& json) {
  std::vector<std::string> keys;
  int depth = 0;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '"') {
      size_t end = i + 1;
      while (end < json.size() && json[end] != '"') end += json[end] == '\\' ? 2 : 1;
      if (depth == 1 && end + 1 < json.size() && json[end + 1] == ':')
        keys.push_back(json.substr(i + 1, end - i - 1));
      i = end;
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return keys;
}

// The table names `name/...` (a top-level folder may be named with its sub-folder: `include/spinhash/`).
bool t_contains_folder(const std::string& table, const std::string& parent, const std::string& name) {
  return table.find("`" + name + "/") != std::string::npos ||
         (!parent.empty() && table.find("`" + parent + "/" + name + "/") != std::string::npos);
}

// True when git ignores `relative` (a path under the source tree): build
// folders, the demo's and the experiments' outputs are not part of the tree.
// Without git (a source archive) only the build folders are skipped.
bool git_ignores(const std::string& relative) {
  const std::string cmd =
      "git -C '" SPINHASH_SOURCE_DIR "' check-ignore -q -- '" + relative + "' </dev/null 2>/dev/null";
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) && WEXITSTATUS(raw) == 0;
}

}  // namespace

TEST_CASE("every configuration field's flag is in --help and in docs/cli.md, and --set is") {
  const spinhash::host::test::TempDir dir("field-mirrors");
  const spinhash::host::test::CliRun help = spinhash::host::test::run_spinhash(dir, "recognize --help");
  REQUIRE(help.exit_code == 0);
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
  REQUIRE_FALSE(docs.empty());
  int flags = 0;
  for (const spinhash::host::ConfigField& f : spinhash::host::config_fields()) {
    if (*f.flag != '\0') {
      INFO("field ", f.key(), ", flag ", f.flag);
      CHECK(help.out.find(long_flag(f.flag)) != std::string::npos);
      CHECK(docs.find("`" + long_flag(f.flag)) != std::string::npos);
      ++flags;
    } else if (*f.stage == '\0') {  // a top-level field: set through another option, which its help names
      INFO("field ", f.key(), " has no flag of its own");
      CHECK(std::string(f.help).rfind("set by --", 0) == 0);
    }  // a stage's field without a flag: --set (test_config_assign.cpp)
  }
  CHECK(flags > 30);
  CHECK(help.out.find("--set") != std::string::npos);
  CHECK(docs.find("`--set") != std::string::npos);
  for (const char* command : {"scene --help", "survey --help", "verify --help"}) {
    INFO(command);
    CHECK(spinhash::host::test::run_spinhash(dir, command).out.find("--set") != std::string::npos);
  }
}

TEST_CASE("the stage tables of docs/api.md are stage_fields.h: names, defaults, ranges, flags, why") {
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/api.md");
  const RecognizerConfig defaults;
  for (const std::string& stage : spinhash::host::stage_ids()) {
    INFO("stage ", stage);
    const auto rows = table_rows(docs, "`" + stage + ".` field");
    size_t k = 0;
    for (const spinhash::host::ConfigField& f : spinhash::host::config_fields()) {
      if (f.stage != stage) continue;
      INFO("field ", f.key());
      REQUIRE(k < rows.size());
      const auto& row = rows[k++];
      REQUIRE(row.size() == 5u);
      CHECK(row[0] == "`" + std::string(f.name) + "`");
      using spinhash::host::FieldKind;
      if (f.kind == FieldKind::BOOL) {
        CHECK(same_default(row[1], f.in<bool>(defaults)));
        CHECK(same_range(row[2], 0, 1, false));
      } else if (f.kind == FieldKind::U32) {
        CHECK(same_default(row[1], f.in<uint32_t>(defaults)));
        CHECK(same_range(row[2], static_cast<double>(f.lo), static_cast<double>(f.hi), true));
      } else {
        CHECK(same_default(row[1], f.in<float>(defaults)));
        CHECK(same_range(row[2], static_cast<float>(f.lo), static_cast<float>(f.hi), true));
      }
      CHECK(row[3] == (*f.flag != '\0' ? "`" + long_flag(f.flag) + "`" : std::string()));
      CHECK(row[4] == f.help);
    }
    CHECK(k == rows.size());
  }
}

TEST_CASE("every statistic has its JSON key in docs/cli.md") {
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
#define SPINHASH_STAT_DOCUMENTED(kind, name, member, json) \
  {                                                        \
    INFO("statistic " #name);                              \
    CHECK(docs.find("`" json "`") != std::string::npos);   \
  }
  SPINHASH_STATS_FIELDS(SPINHASH_STAT_DOCUMENTED)
#undef SPINHASH_STAT_DOCUMENTED
}

TEST_CASE("every key of info and verify --format json is in their output and in docs/cli.md") {
  namespace t = spinhash::host::test;
  const t::TempDir dir("field-mirrors-json");
  const std::string meshes = dir.file("meshes"), db = dir.file("two.shdb");
  REQUIRE(t::run_spinhash(dir, "generate --count 2 -o " + t::shell_quoted(meshes)).exit_code == 0);
  REQUIRE(t::run_spinhash(
              dir, "build --quiet --no-calibration -o " + t::shell_quoted(db) + " " + t::shell_quoted(meshes))
              .exit_code == 0);
  write_bytes(dir.file("bad.shdb"), "not a database");
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
  const t::CliRun info = t::run_spinhash(dir, "info --format json " + t::shell_quoted(db));
  for (const char* key : spinhash::cli::info_keys::kAll) {
    INFO("info key ", std::string(key));
    CHECK(t::contains(info.out, "\"" + std::string(key) + "\":"));
    CHECK(t::contains(docs, "`" + std::string(key) + "`"));
  }
  // Every verify key shows up in one of: a passing check, a failing one, a corrupt blob. The
  // failing check gives each model's name to the other's mesh (a sedan's and a van's): each
  // scan then ranks its own shape's model first, a miss on every machine, whatever its float
  // rounding does to a scan's noise.
  const t::CliRun verify = t::run_spinhash(
      dir, "verify --quiet --queries 1 --format json " + t::shell_quoted(db) + " " + t::shell_quoted(meshes));
  std::vector<std::filesystem::path> objs;
  for (const auto& entry : std::filesystem::directory_iterator(meshes)) objs.push_back(entry.path());
  std::sort(objs.begin(), objs.end());
  REQUIRE(objs.size() == 2u);
  const std::filesystem::path swapped = dir.file("swapped");
  std::filesystem::create_directory(swapped);
  std::filesystem::copy_file(objs[0], swapped / objs[1].filename());
  std::filesystem::copy_file(objs[1], swapped / objs[0].filename());
  const t::CliRun misnamed =
      t::run_spinhash(dir, "verify --quiet --queries 1 --format json " + t::shell_quoted(db) + " " +
                               t::shell_quoted(swapped.string()));
  CHECK(misnamed.exit_code != 0);
  const t::CliRun corrupt =
      t::run_spinhash(dir, "verify --format json " + t::shell_quoted(dir.file("bad.shdb")));
  // A calibrated blob's verify re-runs its calibration (calibration_check).
  const std::string calibrated = dir.file("calibrated.shdb");
  REQUIRE(t::run_spinhash(dir, "build --quiet --calibration-scans 2 --calibration-left-out-scans 2 -o " +
                                   t::shell_quoted(calibrated) + " " + t::shell_quoted(meshes))
              .exit_code == 0);
  const t::CliRun rerun =
      t::run_spinhash(dir, "verify --quiet --queries 1 --calibration-left-out 1 --format json " +
                               t::shell_quoted(calibrated) + " " + t::shell_quoted(meshes));
  const std::string all = verify.out + misnamed.out + corrupt.out + rerun.out;
  for (const char* key : spinhash::cli::verify_keys::kAll) {
    INFO("verify key ", std::string(key));
    CHECK(t::contains(all, "\"" + std::string(key) + "\":"));
    CHECK(t::contains(docs, "`" + std::string(key) + "`"));
  }
}

TEST_CASE(
    "every class key of recognize and scene lines, and every class name, is in docs/cli.md and the output") {
  namespace t = spinhash::host::test;
  const t::TempDir dir("field-mirrors-class");
  const std::string meshes = dir.file("meshes"), db = dir.file("two.shdb"), q = dir.file("q.ply");
  REQUIRE(t::run_spinhash(dir, "generate --count 2 -o " + t::shell_quoted(meshes)).exit_code == 0);
  REQUIRE(t::run_spinhash(
              dir, "build --quiet --no-calibration -o " + t::shell_quoted(db) + " " + t::shell_quoted(meshes))
              .exit_code == 0);
  REQUIRE(t::run_spinhash(dir, "scan " + t::shell_quoted(meshes + "/van-00.obj") + " --random-pose -o " +
                                   t::shell_quoted(q))
              .exit_code == 0);
  const t::CliRun rec =
      t::run_spinhash(dir, "recognize --db " + t::shell_quoted(db) + " " + t::shell_quoted(q));
  REQUIRE(rec.exit_code == 0);
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
  for (const char* key : spinhash::cli::class_keys::kAll) {
    INFO("class key ", std::string(key));
    CHECK(t::contains(rec.out, "\"" + std::string(key) + "\":"));
    CHECK(t::contains(docs, "`" + std::string(key) + "`"));
  }
  CHECK(t::contains(rec.out, "\"class\":\"van\""));  // generate names the fleet by family: van-00 is a van
#define SPINHASH_CLASS_DOCUMENTED(id, Name, name, group, help) \
  {                                                            \
    INFO("class " name);                                       \
    CHECK(t::contains(docs, "`" name "`"));                    \
  }
  SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_DOCUMENTED)
#undef SPINHASH_CLASS_DOCUMENTED
#define SPINHASH_GROUP_DOCUMENTED(id, Name, name, help) \
  {                                                     \
    INFO("group " name);                                \
    CHECK(t::contains(docs, "`" name "`"));             \
  }
  SPINHASH_VEHICLE_GROUPS(SPINHASH_GROUP_DOCUMENTED)
#undef SPINHASH_GROUP_DOCUMENTED
  for (const char* key : spinhash::pipeline::level_keys::kAll) {
    INFO("level key ", std::string(key));
    CHECK(t::contains(rec.out, "\"" + std::string(key) + "\":"));
    CHECK(t::contains(docs, "`" + std::string(key) + "`"));
  }
#define SPINHASH_LEVEL_DOCUMENTED(id, Name, name, help) \
  {                                                     \
    INFO("level " name);                                \
    CHECK(t::contains(docs, "`" name "`"));             \
  }
  SPINHASH_ANSWER_LEVELS(SPINHASH_LEVEL_DOCUMENTED)
#undef SPINHASH_LEVEL_DOCUMENTED
}

TEST_CASE(
    "every scene flag of scene_fields.h is in scene --help, survey's in survey --help, both in docs/cli.md") {
  const spinhash::host::test::TempDir dir("field-mirrors-scene-flags");
  const auto scene = spinhash::host::test::run_spinhash(dir, "scene --help");
  const auto survey = spinhash::host::test::run_spinhash(dir, "survey --help");
  REQUIRE(scene.exit_code == 0);
  REQUIRE(survey.exit_code == 0);
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
  int flags = 0;
#define SPINHASH_SCENE_FLAG(kind, name, lo, hi, flag, help) \
  if (*(flag) != '\0') {                                    \
    INFO("field " #name ", flag " flag);                    \
    CHECK(scene.out.find(flag) != std::string::npos);       \
    CHECK(docs.find("`" flag) != std::string::npos);        \
    ++flags;                                                \
  }
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_SCENE_FLAG)
#undef SPINHASH_SCENE_FLAG
  CHECK(flags == 9);
  for (const char* flag : {"--top", "--max-objects"}) {
    INFO("survey flag ", std::string(flag));
    CHECK(survey.out.find(flag) != std::string::npos);
  }
}

TEST_CASE(
    "the SceneConfig and StreamConfig tables of docs/api.md are scene_fields.h: names, defaults, ranges") {
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/api.md");
  const SceneConfig scene;
  const StreamConfig stream;
  const auto scene_rows = table_rows(docs, "SceneConfig field");
  const auto stream_rows = table_rows(docs, "StreamConfig field");
  size_t k = 0;
#define SPINHASH_ROW(config, rows, kind, name, lo, hi, flag)                              \
  {                                                                                       \
    INFO(#config " field " #name);                                                        \
    REQUIRE(k < rows.size());                                                             \
    const auto& row = rows[k++];                                                          \
    REQUIRE(row.size() == 5u);                                                            \
    CHECK(row[0] == "`" #name "`");                                                       \
    CHECK(same_default(row[1], config.name));                                             \
    CHECK(same_range(row[2], lo, hi, ranged_##kind));                                     \
    CHECK(row[3] == (*(flag) != '\0' ? std::string("`") + (flag) + "`" : std::string())); \
  }
#define SPINHASH_SCENE_ROW(kind, name, lo, hi, flag, help) \
  SPINHASH_ROW(scene, scene_rows, kind, name, lo, hi, flag)
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_SCENE_ROW)
  CHECK(k == scene_rows.size());
  k = 0;
#define SPINHASH_STREAM_ROW(kind, name, lo, hi, flag, help) \
  SPINHASH_ROW(stream, stream_rows, kind, name, lo, hi, flag)
  SPINHASH_STREAM_CONFIG_FIELDS(SPINHASH_STREAM_ROW)
  CHECK(k == stream_rows.size());
#undef SPINHASH_STREAM_ROW
#undef SPINHASH_SCENE_ROW
#undef SPINHASH_ROW
}

TEST_CASE("the status table of docs/api.md is status_list.h, row by row") {
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/api.md");
  const auto rows = table_rows(docs, "value");
  size_t k = 0;
#define SPINHASH_STATUS_ROW(cxx, value, c, word, message)                        \
  {                                                                              \
    INFO("status " #cxx);                                                        \
    REQUIRE(k < rows.size());                                                    \
    const auto& row = rows[k++];                                                 \
    REQUIRE(row.size() == 5u);                                                   \
    CHECK(row[0] == #value);                                                     \
    CHECK(row[1] == "`" #cxx "`");                                               \
    CHECK(row[2] == "`" #c "`");                                                 \
    CHECK(row[3] == "`" word "`");                                               \
    CHECK(row[4] == message);                                                    \
    CHECK(std::string(spinhash::status_name(spinhash::Status::cxx)) == message); \
  }
  SPINHASH_STATUS_LIST(SPINHASH_STATUS_ROW)
#undef SPINHASH_STATUS_ROW
  CHECK(k == rows.size());
}

TEST_CASE("scene's lines carry the object keys of scene_fields.h in order, then crs, time_ms and version") {
  namespace t = spinhash::host::test;
  const t::TempDir dir("field-mirrors-object-keys");
  const std::string meshes = dir.file("meshes"), db = dir.file("two.shdb"), tile = dir.file("tile.las");
  REQUIRE(t::run_spinhash(dir, "generate --count 2 -o " + t::shell_quoted(meshes)).exit_code == 0);
  REQUIRE(t::run_spinhash(
              dir, "build --quiet --no-calibration -o " + t::shell_quoted(db) + " " + t::shell_quoted(meshes))
              .exit_code == 0);
  REQUIRE(t::run_spinhash(dir, "scan " + t::shell_quoted(meshes + "/van-00.obj") + " --ground 12 -o " +
                                   t::shell_quoted(tile))
              .exit_code == 0);
  const t::CliRun scene =
      t::run_spinhash(dir, "scene --db " + t::shell_quoted(db) + " " + t::shell_quoted(tile));
  REQUIRE(scene.exit_code == 0);
  std::vector<std::string> expected;
#define SPINHASH_KEY(key, attribute) expected.push_back(key);
  SPINHASH_SCENE_OBJECT_KEYS(SPINHASH_KEY)
#undef SPINHASH_KEY
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
  for (const std::string& key : expected) {
    INFO("key ", key);
    CHECK(t::contains(docs, "\"" + key + "\":"));  // the sample line of docs/cli.md's scene
  }
  for (const char* key : {"crs", "time_ms", "version"}) expected.push_back(key);
  const auto lines = scene.lines();
  REQUIRE_FALSE(lines.empty());
  for (const std::string& line : lines) CHECK(top_keys(line) == expected);
}

TEST_CASE("README's folder table names every folder of the tree and of firmware-lib/ and host-tools/") {
  // Folders git ignores (build/, demo-out/, out/) are outputs, not the tree.
  namespace fs = std::filesystem;
  const std::string readme = read_bytes(SPINHASH_SOURCE_DIR "/README.md");
  const auto rows = table_rows(readme, "folder");
  std::string table;
  for (const auto& row : rows)
    for (const std::string& cell : row) table += cell + "\n";
  REQUIRE_FALSE(table.empty());
  const fs::path root(SPINHASH_SOURCE_DIR);
  for (const char* parent : {"", "firmware-lib", "host-tools", "tests"})
    for (const auto& entry : fs::directory_iterator(root / parent)) {
      const std::string name = entry.path().filename().string();
      const std::string relative = (fs::path(parent) / name).string();
      if (!entry.is_directory() || name[0] == '.' || name == "build" || name.rfind("build-", 0) == 0 ||
          git_ignores(relative))
        continue;
      INFO("folder ", relative);
      CHECK(t_contains_folder(table, std::string(parent), name));
    }
}
