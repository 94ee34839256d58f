// The LAS reader on the public sample files in ../shared/data/las (PDAL's
// test data: LAS 1.0-1.4, formats 0-3 and 6, extra bytes, VLRs, UTM with a
// 1e-5 z scale, a truncated file, a wrong VLR count), on synthetic malformed
// headers, and the writer's round trip. The expected figures were read from
// the files by an independent Python reader (struct.unpack) in the session
// that wrote this test; the samples' README lists the headers.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"
#include "cloud/las_reader.hpp"
#include "cloud/las_writer.hpp"
#include "cloud_test_support.hpp"

using namespace spinhash::host;

namespace {

const std::string kSamples = SPINHASH_LAS_SAMPLES;  // ../shared/data/las beside the clone

bool samples_present() {
  if (std::filesystem::is_directory(kSamples)) return true;
  MESSAGE("LAS samples not found at " << kSamples << ": skipped (they live in shared/, beside the clone)");
  return false;
}

struct Sample {
  const char* file;
  uint8_t minor, format;
  uint64_t points;
  double first[3];
  uint32_t ground;  // points of class 2
};

const Sample kSamplesExpected[] = {
    {"4_6_crop.las", 2, 3, 23875, {1639798.46, 1454500.25, 7091.26}, 9003},
    {"bad_vlr_count.las", 2, 3, 10, {289814.15, 4320978.61, 170.76}, 10},
    {"extrabytes.las", 4, 3, 1065, {637012.24, 849028.31, 431.66}, 276},
    {"hexbin-crop.las", 2, 1, 38367, {393790.0640609118, 3689098.9261220554, 3208.9747}, 35318},
    {"sample_c.las", 2, 3, 14408, {674522.0000134277, 1206771.7500170898, 627.590029296875}, 1368},
    {"test1_4.las", 4, 6, 1000, {1694510.3869346841, 1816497.966263977, 5598.3596128149675}, 1000},
    {"versions/1.0_0.las", 0, 0, 1, {470692.44, 4602888.9, 16.0}, 1},
    {"versions/1.0_1.las", 0, 1, 1, {470692.44, 4602888.9, 16.0}, 1},
    {"versions/1.1_0.las", 1, 0, 1, {470692.44, 4602888.9, 16.0}, 1},
    {"versions/1.1_1.las", 1, 1, 1, {470692.44, 4602888.9, 16.0}, 1},
    {"versions/1.2_0.las", 2, 0, 1, {470692.44, 4602888.9, 16.0}, 1},
    {"versions/1.2_1.las", 2, 1, 1, {470692.44, 4602888.9, 16.0}, 1},
    {"versions/1.2_2.las", 2, 2, 1, {470692.44, 4602888.9, 16.0}, 1},
    {"versions/1.2_3.las", 2, 3, 1, {470692.44, 4602888.9, 16.0}, 1},
};

std::string load(const std::string& rel) {
  std::string bytes, error;
  REQUIRE_MESSAGE(spinhash::host::read_file(kSamples + "/" + rel, kMaxCloudFileBytes, &bytes, &error), error);
  return bytes;
}

// A valid 3-point LAS 1.2 file from the writer, for breaking field by field.
std::string small_las() {
  std::string bytes, error;
  REQUIRE(las_bytes({500000.5, 4000000.25, 100.0, 500001.0, 4000001.0, 101.0, 500002.0, 4000000.0, 99.5},
                    {2, 1, 6}, &bytes, &error));
  return bytes;
}

void put32(std::string* b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) (*b)[at + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

}  // namespace

TEST_CASE("every LAS sample reads and agrees with its header") {
  if (!samples_present()) return;
  for (const Sample& s : kSamplesExpected) {
    INFO(s.file);
    LasCloud las;
    std::string error;
    REQUIRE_MESSAGE(parse_las(load(s.file), &las, &error), error);
    CHECK(las.header.version_minor == s.minor);
    CHECK(las.header.point_format == s.format);
    CHECK(las.header.point_count == s.points);
    REQUIRE(las.xyz.size() == 3 * s.points);
    for (int a = 0; a < 3; ++a) CHECK(las.xyz[a] == doctest::Approx(s.first[a]).epsilon(1e-12));
    uint32_t ground = 0;
    for (uint8_t c : las.classification) ground += c == kLasClassGround ? 1u : 0u;
    CHECK(ground == s.ground);
    // Every point inside the declared bounds (within half a scale step).
    for (size_t i = 0; i < las.xyz.size(); ++i) {
      const int a = static_cast<int>(i % 3);
      const double slack = 0.5 * las.header.scale[a] + 1e-9;
      CHECK(las.xyz[i] >= las.header.min[a] - slack);
      CHECK(las.xyz[i] <= las.header.max[a] + slack);
    }
  }
}

TEST_CASE("UTM coordinates with a 1e-5 z scale are scaled and offset in double") {
  if (!samples_present()) return;
  LasCloud las;
  std::string error;
  REQUIRE(parse_las(load("hexbin-crop.las"), &las, &error));
  for (size_t i = 0; i < las.xyz.size(); i += 3 * 997) {
    const double steps = (las.xyz[i + 2] - las.header.offset[2]) / las.header.scale[2];
    CHECK(std::fabs(steps - std::round(steps)) < 1e-3);  // exact multiples: no float rounding at 3.7e6 m
    CHECK(las.xyz[i + 1] > 3689000.0);
  }
}

TEST_CASE("a LAS file that declares more points than it holds is refused, not zero-filled") {
  if (!samples_present()) return;
  LasCloud las;
  std::string error;
  CHECK_FALSE(parse_las(load("versions/1.2-no-points.las"), &las, &error));
  CHECK(error.find("truncated") != std::string::npos);
  CHECK(las.xyz.empty());
  std::vector<double> xyz;
  CHECK_FALSE(spinhash::host::test::try_read_cloud(kSamples + "/versions/1.2-no-points.las", &xyz, &error));
}

TEST_CASE("read_cloud takes LAS by its signature") {
  if (!samples_present()) return;
  std::vector<double> xyz;
  std::string error;
  REQUIRE_MESSAGE(spinhash::host::test::try_read_cloud(kSamples + "/sample_c.las", &xyz, &error), error);
  CHECK(xyz.size() == 3u * 14408u);
}

TEST_CASE("malformed LAS headers get a clear error, never a crash") {
  const std::string good = small_las();
  LasCloud las;
  std::string error;
  REQUIRE_MESSAGE(parse_las(good, &las, &error), error);
  REQUIRE(las.xyz.size() == 9u);

  struct Break {
    const char* what;
    size_t at;
    uint32_t value;
    int bytes;
    const char* message;
  };
  const Break breaks[] = {
      {"version 2.0", 24, 2, 1, "version"},
      {"version 1.9", 25, 9, 1, "version"},
      {"header size beyond the file", 94, 60000, 2, "header size"},
      {"header size below 227", 94, 100, 2, "header size"},
      {"point offset beyond the file", 96, 1u << 30, 4, "offset to point data"},
      {"point offset inside the header", 96, 10, 4, "offset to point data"},
      {"point format 11", 104, 11, 1, "format"},
      {"LAZ bit set", 104, 0x81, 1, "LAZ"},
      {"record length too short", 105, 12, 2, "record length"},
      {"a million points in 84 bytes", 107, 1000000, 4, "truncated"},
  };
  for (const Break& b : breaks) {
    INFO(b.what);
    std::string bad = good;
    for (int i = 0; i < b.bytes; ++i) bad[b.at + i] = static_cast<char>((b.value >> (8 * i)) & 0xFF);
    CHECK_FALSE(parse_las(bad, &las, &error));
    CHECK(error.find(b.message) != std::string::npos);
    CHECK(las.xyz.empty());
  }
  std::string zero_scale = good;
  std::memset(&zero_scale[131], 0, 8);
  CHECK_FALSE(parse_las(zero_scale, &las, &error));
  CHECK(error.find("scale") != std::string::npos);
  CHECK_FALSE(parse_las(good.substr(0, 200), &las, &error));  // shorter than the header
  std::string cut = good;
  cut.pop_back();  // the last point loses a byte
  CHECK_FALSE(parse_las(cut, &las, &error));
  put32(&cut, 107, 2);  // two whole points: fine
  CHECK(parse_las(cut, &las, &error));
}

TEST_CASE("compressed and foreign formats are named, with how to convert them") {
  struct Foreign {
    std::string bytes;
    const char* names;
  };
  const Foreign foreign[] = {{std::string("\x1f\x8b\x08\x00", 4) + "xxxx", "gzip"},
                             {std::string("PK\x03\x04", 4) + "xxxx", "zip"},
                             {"ASTM-E57 and more", "E57"},
                             {"# .PCD v0.7 - Point Cloud Data\nVERSION 0.7\n", "PCD"}};
  for (const Foreign& f : foreign) {
    std::vector<double> xyz;
    std::string error;
    CHECK_FALSE(spinhash::host::test::try_read_cloud_bytes(f.bytes, &xyz, &error));
    CHECK(error.find(f.names) != std::string::npos);
    CHECK(error.find("first") != std::string::npos);  // "convert/decompress ... first"
  }
  std::string laz = small_las();
  laz[104] = static_cast<char>(0x83);
  std::vector<double> xyz;
  std::string error;
  CHECK_FALSE(spinhash::host::test::try_read_cloud_bytes(laz, &xyz, &error));
  CHECK(error.find("LAZ") != std::string::npos);
  CHECK(error.find("laszip") != std::string::npos);
}

TEST_CASE("the LAS writer round-trips georeferenced points to the millimetre, with classes") {
  const std::vector<double> xyz{431000.1234, 4020000.5678, 85.4321, 431010.0, 4020005.0, 86.0};
  std::string bytes, error;
  REQUIRE(las_bytes(xyz, {2, 6}, &bytes, &error));
  LasCloud las;
  REQUIRE_MESSAGE(parse_las(bytes, &las, &error), error);
  REQUIRE(las.xyz.size() == xyz.size());
  for (size_t i = 0; i < xyz.size(); ++i)
    CHECK(std::fabs(las.xyz[i] - xyz[i]) <= 0.5 * kLasWriteScale + 1e-9);
  CHECK(las.classification == std::vector<uint8_t>{2, 6});
  CHECK_FALSE(las_bytes({1.0, 2.0, std::nan("")}, {}, &bytes, &error));
  CHECK(error.find("not finite") != std::string::npos);
}
