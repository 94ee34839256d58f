// spinhash build's calibration end to end on a small generated fleet: the
// blob holds a fitted table that info prints for every level and band, the
// same whatever the thread count, the clutter it was fitted against, and
// verify re-runs it.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "cli_runner.hpp"
#include "spinhash/calibration.hpp"

using namespace spinhash::host::test;

namespace {

// Few runs: every band of this fleet is too small for a 0.99 target, which
// is what info must then say.
const char* kSmall =
    "--quiet --calibration-scans 3 --calibration-left-out-scans 3 --calibration-max-left-out 3 "
    "--calibration-seed 5 --agree-precision 0.98 ";

}  // namespace

TEST_CASE("build calibrates every level; info prints each band; the blob does not depend on the threads") {
  const TempDir dir("calibration-build");
  const std::string meshes = dir.file("fleet"), one = dir.file("one.shdb"), two = dir.file("two.shdb");
  REQUIRE(run_spinhash(dir, "generate --count 4 -o " + shell_quoted(meshes)).exit_code == 0);
  const CliRun a = run_spinhash(
      dir, std::string("build ") + kSmall + "--jobs 1 -o " + shell_quoted(one) + " " + shell_quoted(meshes));
  INFO(a.err);
  REQUIRE(a.exit_code == 0);
  CHECK(contains(a.err, "calibrated on"));
  const CliRun b = run_spinhash(
      dir, std::string("build ") + kSmall + "--jobs 2 -o " + shell_quoted(two) + " " + shell_quoted(meshes));
  REQUIRE(b.exit_code == 0);
  CHECK(read_bytes(one) == read_bytes(two));

  const CliRun info = run_spinhash(dir, "info " + shell_quoted(one));
  REQUIRE(info.exit_code == 0);
  CHECK(contains(info.out, "calibration   target precision 0.99: 3 scans per model, 3 models left out"));
  for (uint32_t l = 1; l <= spinhash::kCalibratedLevels; ++l)
    for (const char* band : {"0-15", "15-30", "30-60", "60-120", "120-240", "240+"}) {
      char row[64];
      for (const char* pass : {"full", "first", "agree"}) {  // a table per pass, and the cascade's stop
        std::snprintf(row, sizeof row, "  %-6s %-8s %-12s", pass, spinhash::answer_level_name(l), band);
        CAPTURE(row);
        CHECK(contains(info.out, row));
      }
    }
  CHECK(contains(info.out, "never: too few runs"));
  CHECK(contains(info.out, "  agree  fitted to precision 0.98\n"));

  const CliRun json = run_spinhash(dir, "info --format json " + shell_quoted(one));
  REQUIRE(json.exit_code == 0);
  CHECK(contains(json.out, "{\"pass\":\"full\",\"source\":\"fitted\""));
  CHECK(contains(json.out, "{\"pass\":\"first\",\"source\":\"fitted\",\"target_precision\":0.99,"));
  CHECK(contains(json.out, "{\"pass\":\"agree\",\"source\":\"fitted\",\"target_precision\":0.98,"));
  CHECK(contains(json.out, "\"bands\":[0,15,30,60,120,240]"));
  CHECK(contains(json.out, "\"clutter\":\"tiles\""));
  CHECK(contains(info.out, " clutter scans (trees, walls, crates, buildings), seed 5"));
  for (uint32_t l = 1; l <= spinhash::kCalibratedLevels; ++l)
    CHECK(
        contains(json.out, std::string("{\"level\":\"") + spinhash::answer_level_name(l) + "\",\"cells\":["));

  // Fitted against vehicle-sized clutter too: the blob says so, and verify
  // re-runs its calibration against the same kinds (the last lines below).
  const std::string sized = dir.file("sized.shdb");
  const CliRun s =
      run_spinhash(dir, std::string("build ") + kSmall + "--calibration-clutter vehicle-sized -o " +
                            shell_quoted(sized) + " " + shell_quoted(meshes));
  INFO(s.err);
  REQUIRE(s.exit_code == 0);
  CHECK(read_bytes(sized) != read_bytes(one));
  CHECK(contains(run_spinhash(dir, "info --format json " + shell_quoted(sized)).out,
                 "\"clutter\":\"vehicle-sized\""));
  CHECK(contains(run_spinhash(dir, "info " + shell_quoted(sized)).out,
                 "freight containers, bushes, heaps), seed 5"));
  const CliRun unknown =
      run_spinhash(dir, "build --calibration-clutter boxes -o " + shell_quoted(dir.file("no.shdb")) + " " +
                            shell_quoted(meshes));
  CHECK(unknown.exit_code == 2);
  CHECK(contains(unknown.err, "--calibration-clutter"));

  // A blob built without calibration says so; verify re-runs a fitted one.
  const std::string bare = dir.file("bare.shdb");
  REQUIRE(run_spinhash(dir,
                       "build --quiet --no-calibration -o " + shell_quoted(bare) + " " + shell_quoted(meshes))
              .exit_code == 0);
  CHECK(contains(run_spinhash(dir, "info " + shell_quoted(bare)).out, "calibration   none"));
  const CliRun verify =
      run_spinhash(dir, "verify --quiet --queries 1 --calibration-left-out 2 --format json " +
                            shell_quoted(sized) + " " + shell_quoted(meshes));
  INFO(verify.err);
  CHECK(contains(verify.out, "\"calibration\":\"fitted\""));
  CHECK(contains(verify.out, "{\"pass\":\"full\",\"level\":\"model\",\"flagged\":"));
  CHECK(contains(verify.out, "{\"pass\":\"first\",\"level\":\"model\",\"flagged\":"));
  CHECK(contains(verify.out, "{\"pass\":\"agree\",\"level\":\"model\",\"flagged\":"));
}
