// The command line and its documentation against the field lists of
// spinhash/config_fields.h: every configuration field has its flag in
// `recognize --help` and in docs/cli.md, every statistic its JSON key there.
#include <doctest/doctest.h>

#include <string>

#include "cli/report_keys.hpp"
#include "cli_runner.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/vehicle_classes.h"

namespace {

using spinhash::host::test::read_bytes;
using spinhash::host::test::write_bytes;

// "-W,--top-w" -> "--top-w"; "!--no-refine" -> "--no-refine".
std::string long_flag(const std::string& spec) {
  const size_t at = spec.find("--");
  return at == std::string::npos ? spec : spec.substr(at);
}

}  // namespace

TEST_CASE("every configuration field has its flag in --help and in docs/cli.md") {
  const spinhash::host::test::TempDir dir("field-mirrors");
  const spinhash::host::test::CliRun help = spinhash::host::test::run_spinhash(dir, "recognize --help");
  REQUIRE(help.exit_code == 0);
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
  REQUIRE_FALSE(docs.empty());
  int flags = 0;
#define SPINHASH_FLAG_DOCUMENTED(kind, name, lo, hi, flag, help_text) \
  if (*(flag) != '\0') {                                              \
    INFO("field " #name ", flag " flag);                              \
    CHECK(help.out.find(long_flag(flag)) != std::string::npos);       \
    CHECK(docs.find("`" + long_flag(flag)) != std::string::npos);     \
    ++flags;                                                          \
  } else {                                                            \
    INFO("field " #name " has no flag of its own");                   \
    CHECK(std::string(help_text).rfind("set by --", 0) == 0);         \
  }
  SPINHASH_CONFIG_FIELDS(SPINHASH_FLAG_DOCUMENTED)
#undef SPINHASH_FLAG_DOCUMENTED
  CHECK(flags > 30);
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
  REQUIRE(t::run_spinhash(dir, "build --quiet -o " + t::shell_quoted(db) + " " + t::shell_quoted(meshes))
              .exit_code == 0);
  write_bytes(dir.file("bad.shdb"), "not a database");
  const std::string docs = read_bytes(SPINHASH_SOURCE_DIR "/docs/cli.md");
  const t::CliRun info = t::run_spinhash(dir, "info --format json " + t::shell_quoted(db));
  for (const char* key : spinhash::cli::info_keys::kAll) {
    INFO("info key ", std::string(key));
    CHECK(t::contains(info.out, "\"" + std::string(key) + "\":"));
    CHECK(t::contains(docs, "`" + std::string(key) + "`"));
  }
  // Every verify key shows up in one of: a passing check, a failing one (0.9 m noise: both
  // vehicles ranked second, deterministically for the seed), a corrupt blob.
  const t::CliRun verify = t::run_spinhash(
      dir, "verify --quiet --queries 1 --format json " + t::shell_quoted(db) + " " + t::shell_quoted(meshes));
  const t::CliRun noisy = t::run_spinhash(dir, "verify --quiet --queries 1 --noise 0.9 --format json " +
                                                   t::shell_quoted(db) + " " + t::shell_quoted(meshes));
  const t::CliRun corrupt =
      t::run_spinhash(dir, "verify --format json " + t::shell_quoted(dir.file("bad.shdb")));
  const std::string all = verify.out + noisy.out + corrupt.out;
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
  REQUIRE(t::run_spinhash(dir, "build --quiet -o " + t::shell_quoted(db) + " " + t::shell_quoted(meshes))
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
#define SPINHASH_CLASS_DOCUMENTED(id, Name, name, help) \
  {                                                     \
    INFO("class " name);                                \
    CHECK(t::contains(docs, "`" name "`"));             \
  }
  SPINHASH_VEHICLE_CLASSES(SPINHASH_CLASS_DOCUMENTED)
#undef SPINHASH_CLASS_DOCUMENTED
}
