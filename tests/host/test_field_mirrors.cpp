// The command line and its documentation against the field lists of
// spinhash/config_fields.h: every configuration field has its flag in
// `recognize --help` and in docs/cli.md, every statistic its JSON key there.
#include <doctest/doctest.h>

#include <string>

#include "cli_runner.hpp"
#include "spinhash/config_fields.h"

namespace {

using spinhash::host::test::read_bytes;

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
