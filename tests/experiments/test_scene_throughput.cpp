// `scene-throughput run` (experiments/scene_throughput/) times the scene
// path by stage with each tile decoded once: its LAZ decoding is timed
// inside the stream's own pass, and each row carries the records the
// LAS/LAZ reader decoded for its tile, which a second pass over the tile
// would double. CSV columns are read by name (csv_columns.hpp).
#include <doctest/doctest.h>

#include <cstdlib>
#include <set>
#include <string>

#include "cli_runner.hpp"
#include "csv_columns.hpp"
#include "geometry_test_support.hpp"

namespace {

using namespace spinhash::host::test;

int run_bench(const TempDir& dir, const std::string& args, const std::string& out = "/dev/null") {
  const std::string cmd = "'" SPINHASH_SCENE_THROUGHPUT_BINARY "' " + args + " > " + shell_quoted(out) +
                          " 2>> " + shell_quoted(dir.file("stderr.txt"));
  return std::system(cmd.c_str());
}

}  // namespace

TEST_CASE("scene-throughput run decodes each tile once and times its decoding in that pass") {
  TempDir dir("scene-throughput");
  // Two sparse tiles: 120 000 points (three LAZ chunks of 50 000) and 30 000.
  const std::string big = dir.file("big.laz"), small = dir.file("small.laz");
  REQUIRE(run_bench(dir, "sparse " + shell_quoted(big) + " 120000 300") == 0);
  REQUIRE(run_bench(dir, "sparse " + shell_quoted(small) + " 30000 150") == 0);
  const std::string csv = dir.file("throughput.csv");
  REQUIRE_MESSAGE(run_bench(dir,
                            "run " + shell_quoted(SPINHASH_GOLDEN_BLOB) + " " + shell_quoted(big) + " " +
                                shell_quoted(small),
                            csv) == 0,
                  read_bytes(dir.file("stderr.txt")));
  const CsvColumns table(read_bytes(csv));
  for (const char* column : {"tile", "stage", "cpu_s", "points_per_s", "records_decoded"}) {
    CAPTURE(column);
    REQUIRE(table.has(column));
  }
  const std::set<std::string> stages = {
      "laz_decoding", "along_track_order",   "terrain", "segmentation", "stream_rest",
      "recognition",  "all_but_recognition", "total"};
  REQUIRE(table.rows() == 2 * stages.size());
  size_t big_rows = 0, small_rows = 0;
  double decoding[2] = {-1.0, -1.0}, total[2] = {-1.0, -1.0};
  for (size_t i = 0; i < table.rows(); ++i) {
    const std::string tile = table.cell(i, "tile"), stage = table.cell(i, "stage");
    CAPTURE(tile);
    CAPTURE(stage);
    CHECK(stages.count(stage) == 1u);
    REQUIRE((tile == "big.laz" || tile == "small.laz"));
    const int t = tile == "big.laz" ? 0 : 1;
    (t == 0 ? big_rows : small_rows) += 1;
    // Every record of the tile decoded, and only once (a separate decoding
    // pass would make these 240 000 and 60 000).
    CHECK(table.cell(i, "records_decoded") == std::string(t == 0 ? "120000" : "30000"));
    if (stage == "laz_decoding") decoding[t] = table.number(i, "cpu_s");
    if (stage == "total") total[t] = table.number(i, "cpu_s");
  }
  CHECK(big_rows == stages.size());
  CHECK(small_rows == stages.size());
  for (int t = 0; t < 2; ++t) {
    CAPTURE(t);
    // Decoding is timed (the wrapped reader was called) and is part of the
    // tile's one pass, so within its total.
    CHECK(decoding[t] > 0.0);
    CHECK(decoding[t] <= total[t]);
  }
}
