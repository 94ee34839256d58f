// PointSource on text and LAS files written here: chunks of any size give
// the points read_cloud gives, headers come without points, points a LAS
// file marks as noise or withheld are left out and counted, and malformed
// files fail with read_cloud's messages, naming the file.
#include <doctest/doctest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"
#include "cloud/cloud_writer.hpp"
#include "cloud/las_writer.hpp"
#include "cloud/point_source.hpp"
#include "cloud_test_support.hpp"

using namespace spinhash::host;

namespace {

std::string write_temp(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() / ("spinhash_point_source_" + name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

// noise: when given, the source's points_noise() once read.
std::vector<double> read_chunked(const std::string& path, size_t chunk, uint64_t* noise = nullptr) {
  auto src = open_point_source(path);
  std::vector<double> all, buf(3 * chunk);
  for (size_t n; (n = src->read(buf.data(), chunk)) > 0;) {
    CHECK(n <= chunk);
    all.insert(all.end(), buf.begin(), buf.begin() + 3 * n);
  }
  if (noise != nullptr) *noise = src->points_noise();
  return all;
}

std::string failure(const std::string& path) {
  try {
    read_chunked(path, 16);
  } catch (const CloudError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a text cloud read in chunks of 1, 7 and 4096 gives read_cloud's points") {
  std::string text = "# a comment\n\nX;Y;Z;intensity\n";
  for (int i = 0; i < 5000; ++i)
    text += std::to_string(500000 + i) + ",25;" + std::to_string(4000000 - i) + ";" + std::to_string(i % 97) +
            ";7\r\n";
  text += "1;2;3";  // no newline at the end
  const std::string path = write_temp("cloud.txt", text);
  std::vector<double> whole;
  std::string error;
  REQUIRE_MESSAGE(spinhash::host::test::try_read_cloud(path, &whole, &error), error);
  REQUIRE(whole.size() == 3 * 5001u);
  CHECK(whole[0] == 500000.25);
  for (size_t chunk : {size_t{1}, size_t{7}, size_t{4096}}) CHECK(read_chunked(path, chunk) == whole);
  CHECK(open_point_source(path)->header().format == "text");
  CHECK_FALSE(open_point_source(path)->header().count_known);
  std::filesystem::remove(path);
}

TEST_CASE("malformed text clouds fail with read_cloud's message and the file name") {
  const std::pair<std::string, std::string> cases[] = {
      {std::string("1 2 3\n\0\x01\x02", 9), "binary data"},
      {"1 2 3\n4 5\n", "text cloud line 2"},
      {"# only a comment\n\n", "no points"},
      {"a b c\n1 2 3\n", "no x, y and z"},
  };
  for (const auto& [bytes, message] : cases) {
    INFO(message);
    const std::string path = write_temp("bad.txt", bytes);
    const std::string why = failure(path);
    CHECK(why.find(message) != std::string::npos);
    CHECK(why.find(path) != std::string::npos);
    std::filesystem::remove(path);
  }
  CHECK(failure("/nonexistent/cloud.txt").find("not found") != std::string::npos);
}

TEST_CASE("a LAS file read in chunks gives read_cloud's points; its header comes without them") {
  std::vector<double> xyz;
  for (int i = 0; i < 10000; ++i) {
    xyz.push_back(431000.0 + 0.01 * i);
    xyz.push_back(4020000.0 - 0.02 * i);
    xyz.push_back(85.0 + 0.001 * (i % 300));
  }
  std::string bytes, error;
  REQUIRE(las_bytes(xyz, std::vector<uint8_t>(10000, 2), &bytes, &error));
  const std::string path = write_temp("tile.las", bytes);
  std::vector<double> whole;
  REQUIRE(spinhash::host::test::try_read_cloud(path, &whole, &error));
  for (size_t chunk : {size_t{1}, size_t{7}, size_t{4096}, size_t{10000}})
    CHECK(read_chunked(path, chunk) == whole);
  const CloudHeader h = read_cloud_header(path);
  CHECK(h.format == "las");
  CHECK(h.point_count == 10000);
  CHECK(h.bounds_known);
  CHECK(h.min[0] == doctest::Approx(431000.0));
  CHECK_FALSE(h.crs.known());
  // Cut inside the points: refused as truncated when opened (the header's
  // count is checked against the bytes present).
  const std::string cut = write_temp("cut.las", bytes.substr(0, bytes.size() - 10));
  CHECK(failure(cut).find("truncated") != std::string::npos);
  std::filesystem::remove(path);
  std::filesystem::remove(cut);
}

TEST_CASE("LAS points marked noise (classes 7 and 18) or withheld are left out and counted") {
  // Formats 0-5: the class in the low 5 bits, withheld the top bit.
  const std::vector<double> xyz = {10, 20, 1, 11, 20, -30, 12, 20, 400, 13, 20, 1, 14, 20, 1};
  std::string bytes, error;
  REQUIRE(las_bytes(xyz, {2, 7, 18, 1, 6}, &bytes, &error));
  constexpr size_t kRecordLength = 28, kClassAt = 15;  // las_writer.hpp: format 1
  const size_t points_at = bytes.size() - 5 * kRecordLength;
  bytes[points_at + 3 * kRecordLength + kClassAt] = static_cast<char>(1 | 0x80);  // withheld
  const std::string path = write_temp("noise.las", bytes);
  for (size_t chunk : {size_t{1}, size_t{2}, size_t{64}}) {
    CAPTURE(chunk);
    uint64_t noise = 0;
    CHECK(read_chunked(path, chunk, &noise) == std::vector<double>{10, 20, 1, 14, 20, 1});
    CHECK(noise == 3u);
  }
  CHECK(dropped_note(0, PointFilter{}).empty());
  CHECK(dropped_note(3, PointFilter{}) ==
        "3 points the file marks as noise (ASPRS classes 7 and 18) or withheld: left out");
  // A class the user names (--drop-class) goes too, and is counted.
  PointFilter sixes;
  REQUIRE(add_drop_classes("6", &sixes, &error));
  auto named = open_point_source(path, sixes);
  CHECK(read_all_points(*named) == std::vector<double>{10, 20, 1});
  CHECK(named->points_noise() == 4u);
  CHECK(dropped_note(4, sixes) ==
        "4 points the file marks as noise (ASPRS classes 7 and 18), withheld or of class 6, as asked: left "
        "out");
  std::filesystem::remove(path);
  // Format 6 (LAS 1.4): a public sample holding 25 class-7 points.
  const std::string sample =
      std::string(SPINHASH_LAZ_SAMPLES) + "/crs/file_with_both_wkt_and_geotiff_vlrs.las";
  if (!std::filesystem::exists(sample)) return;
  auto src = open_point_source(sample);
  CHECK(src->header().las_point_format == 6);
  CHECK(read_all_points(*src).size() / 3 == src->header().point_count - 25);
  CHECK(src->points_noise() == 25u);
}

TEST_CASE("classes named to be left out: parsed from the command line's lists, whole classes 0-255 only") {
  PointFilter f;
  std::string error;
  REQUIRE(add_drop_classes("65,66", &f, &error));
  REQUIRE(add_drop_classes("0", &f, &error));
  CHECK(f.extra_classes() == std::vector<int>{0, 65, 66});
  CHECK(f.classes() == std::vector<int>{0, 7, 18, 65, 66});
  CHECK(classes_text(f) == "0,7,18,65,66");
  CHECK(classes_text(PointFilter{}) == "7,18");
  REQUIRE(add_drop_classes("7", &f, &error));  // noise already: no change
  CHECK(f.extra_classes() == std::vector<int>{0, 65, 66});
  CHECK(dropped_note(9, f).find("of class 0, 65 or 66, as asked") != std::string::npos);
  for (const char* bad : {"", "256", "-1", "6x", "6,,7", "1.5", "99999999999999999999"}) {
    CAPTURE(bad);
    PointFilter g;
    CHECK_FALSE(add_drop_classes(bad, &g, &error));
    CHECK(error.find("not a LAS class") != std::string::npos);
    CHECK(g.extra_classes().empty());  // nothing of a refused list is kept
  }
  CHECK_FALSE(add_drop_classes(std::vector<int>{3, 300}, &f, &error));
  CHECK(error == "300 is not a LAS class (0 to 255)");
  CHECK_FALSE(f.named[3]);
}

TEST_CASE("a class above 31 (LAS 1.4 formats) named to be left out goes, counted with the noise") {
  // A public format-8 sample whose producer put 539 points in class 65.
  const std::string sample = std::string(SPINHASH_LAZ_SAMPLES) + "/no-twin/format8-nir-extrabytes.laz";
  if (!std::filesystem::exists(sample)) return;
  auto plain = open_point_source(sample);
  const size_t all = read_all_points(*plain).size() / 3;
  PointFilter f;
  std::string error;
  REQUIRE(add_drop_classes("65", &f, &error));
  auto filtered = open_point_source(sample, f);
  CHECK(filtered->header().las_point_format == 8);
  CHECK(read_all_points(*filtered).size() / 3 == all - 539);
  CHECK(filtered->points_noise() == plain->points_noise() + 539);
}

TEST_CASE("a binary PLY read in chunks gives read_cloud's points; other PLY falls back to the whole reader") {
  std::vector<double> xyz;
  for (int i = 0; i < 3000; ++i) {
    xyz.push_back(0.5 * i);
    xyz.push_back(-0.25 * i);
    xyz.push_back(1e6 + i);
  }
  std::string error;
  const std::string binary =
      (std::filesystem::temp_directory_path() / "spinhash_point_source_b.ply").string();
  const std::string ascii = (std::filesystem::temp_directory_path() / "spinhash_point_source_a.ply").string();
  REQUIRE(write_ply(binary, xyz, true, &error));
  REQUIRE(write_ply(ascii, xyz, false, &error));
  for (const std::string& path : {binary, ascii}) {
    INFO(path);
    std::vector<double> whole;
    REQUIRE(spinhash::host::test::try_read_cloud(path, &whole, &error));
    CHECK(whole == xyz);
    for (size_t chunk : {size_t{1}, size_t{7}, size_t{4096}}) CHECK(read_chunked(path, chunk) == xyz);
    const CloudHeader h = read_cloud_header(path);
    CHECK(h.format == "ply");
    CHECK(h.point_count == 3000);
  }
  // A binary PLY cut short: the whole reader names the truncation.
  std::ifstream in(binary, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const std::string cut = write_temp("cut.ply", bytes.substr(0, bytes.size() - 5));
  CHECK(failure(cut).find("truncated") != std::string::npos);
  for (const std::string& p : {binary, ascii, cut}) std::filesystem::remove(p);
}
