#include "cloud/cloud_reader.hpp"
#include "cloud/cloud_writer.hpp"
#include "cloud/ply_header.hpp"
#include "cloud_test_support.hpp"
#include "geometry_test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

namespace sh = spinhash::host;
using sh::test::TempDir;
using sh::test::write_bytes;

namespace {

// Raw bytes of a value in the given byte order.
template <typename T>
std::string raw(T value, bool big_endian) {
  std::string bytes(sizeof(T), '\0');
  std::memcpy(bytes.data(), &value, sizeof(T));
  const uint16_t probe = 1;
  const bool host_big = *reinterpret_cast<const uint8_t*>(&probe) == 0;
  if (host_big != big_endian) std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

bool parse(const std::string& bytes, std::vector<double>* xyz, std::string* error) {
  return spinhash::host::test::try_read_cloud_bytes(bytes, xyz, error);
}

// Fails to parse, and the error mentions `words`.
void check_rejected(const std::string& bytes, const std::string& words) {
  std::vector<double> xyz = {1.0};
  std::string error;
  CAPTURE(words);
  CHECK_FALSE(parse(bytes, &xyz, &error));
  CHECK(xyz.empty());
  CHECK_MESSAGE(error.find(words) != std::string::npos, error);
}

const std::string kXyzFloatHeader =
    "element vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n";

std::string two_point_binary_le() {
  std::string ply = "ply\nformat binary_little_endian 1.0\n" + kXyzFloatHeader;
  for (float v : {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f}) ply += raw(v, false);
  return ply;
}

}  // namespace

TEST_CASE("PLY round trips exactly in binary and ascii, also at UTM coordinates") {
  TempDir dir("cloud");
  std::vector<double> xyz;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-50.0, 50.0);  // values only, not compared across libraries
  for (int i = 0; i < 500; ++i) {
    xyz.insert(xyz.end(), {500000.0 + jitter(rng), 4000000.0 + jitter(rng), 100.0 + jitter(rng)});
  }
  xyz[7] = NAN;
  for (bool binary : {true, false}) {
    CAPTURE(binary);
    const std::string path = dir.file(binary ? "b.ply" : "a.ply");
    std::string error;
    REQUIRE_MESSAGE(sh::write_ply(path, xyz, binary, &error), error);
    CHECK_FALSE(std::filesystem::exists(path + ".tmp"));
    std::vector<double> back;
    REQUIRE_MESSAGE(spinhash::host::test::try_read_cloud(path, &back, &error), error);
    REQUIRE(back.size() == xyz.size());
    CHECK(std::isnan(back[7]));  // NaN passes through
    back[7] = xyz[7] = 0.0;
    CHECK(back == xyz);
    xyz[7] = NAN;
  }
  std::string error;
  CHECK_FALSE(sh::write_ply(dir.file("no/such/dir.ply"), xyz, true, &error));
  CHECK_FALSE(sh::write_ply(dir.file("odd.ply"), {1.0, 2.0}, true, &error));
  std::vector<double> empty;
  REQUIRE(sh::write_ply(dir.file("empty.ply"), {}, true, &error));
  CHECK(spinhash::host::test::try_read_cloud(dir.file("empty.ply"), &empty, &error));
  CHECK(empty.empty());
}

TEST_CASE("hand-written binary big-endian PLY with mixed types and extra properties") {
  std::string ply =
      "ply\nformat binary_big_endian 1.0\ncomment made by hand\nobj_info test\n"
      "element camera 1\nproperty float64 focal\nproperty list uint8 int32 ids\n"
      "element vertex 2\nproperty uchar red\nproperty float32 x\nproperty double y\n"
      "property int16 extra\nproperty float z\nproperty list uchar float normals\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  ply += raw(35.0, true) + raw(uint8_t(2), true) + raw(int32_t(7), true) + raw(int32_t(8), true);
  const double points[2][3] = {{1.5, -2.25, 3.0}, {500000.125, 4000000.5, -7.0}};
  for (const auto& p : points) {
    ply += raw(uint8_t(200), true) + raw(float(p[0]), true) + raw(p[1], true) + raw(int16_t(-5), true) +
           raw(float(p[2]), true);
    ply += raw(uint8_t(1), true) + raw(0.5f, true);
  }
  ply += raw(uint8_t(3), true) + raw(int32_t(0), true) + raw(int32_t(1), true) + raw(int32_t(0), true);
  std::vector<double> xyz;
  std::string error;
  REQUIRE_MESSAGE(parse(ply, &xyz, &error), error);
  REQUIRE(xyz.size() == 6);
  CHECK(xyz[0] == 1.5);
  CHECK(xyz[1] == -2.25);
  CHECK(xyz[2] == 3.0);
  CHECK(xyz[3] == float(500000.125));  // float x: float precision, as stored
  CHECK(xyz[4] == 4000000.5);          // double y: exact
  CHECK(xyz[5] == -7.0);
}

TEST_CASE("face element after the vertices, binary and ascii") {
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar uint vertex_indices\n"
      "property uchar flags\nend_header\n";
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) binary += raw(v, false);
  for (int f = 0; f < 2; ++f) {
    binary += raw(uint8_t(3), false);
    for (uint32_t i : {0u, 1u, 2u}) binary += raw(i, false);
    binary += raw(uint8_t(9), false);
  }
  std::vector<double> xyz;
  std::string error;
  REQUIRE_MESSAGE(parse(binary, &xyz, &error), error);
  CHECK(xyz == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});

  const std::string ascii =
      "ply\r\nformat ascii 1.0\r\ncomment CRLF file\r\nelement vertex 3\r\nproperty double x\r\n"
      "property int intensity\r\nproperty double y\r\nproperty double z\r\n"
      "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
      "1.5 7 2 3\r\n-4e3 8 +5 nan\r\n7 9 8 9\r\n3 0 1 2\r\n";
  REQUIRE_MESSAGE(parse(ascii, &xyz, &error), error);
  REQUIRE(xyz.size() == 9);
  CHECK(xyz[0] == 1.5);
  CHECK(xyz[3] == -4000.0);
  CHECK(xyz[4] == 5.0);
  CHECK(std::isnan(xyz[5]));
  CHECK(xyz[8] == 9.0);
}

TEST_CASE("malformed PLY files fail cleanly with a clear message") {
  const std::string good = two_point_binary_le();
  const std::string header = "ply\nformat binary_little_endian 1.0\n";
  check_rejected(good.substr(0, good.size() - 3), "truncated");
  check_rejected(good + "xx", "unexpected data");
  check_rejected(
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n" +
          good.substr(good.find("end_header\n") + 11),
      "claims 3 entries");
  check_rejected(header +
                     "element vertex 1000000000000\nproperty float x\nproperty float y\n"
                     "property float z\nend_header\n" +
                     std::string(24, '\0'),
                 "claims 1000000000000");
  check_rejected(
      "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n1 2 3\n",
      "too short");
  check_rejected(header + "element vertex 1\nproperty float128 x\nend_header\n", "unknown type");
  check_rejected(header + "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n",
                 "missing end_header");
  check_rejected(
      header + "element vertex 1\nproperty float x\nproperty float z\nend_header\n" + std::string(8, '\0'),
      "no property y");
  check_rejected(header +
                     "element vertex 1\nproperty int x\nproperty float y\nproperty float z\n"
                     "end_header\n" +
                     std::string(12, '\0'),
                 "float or double");
  check_rejected(header + "element vertex -5\nend_header\n", "invalid element count");
  check_rejected(header + "element vertex 1x\nend_header\n", "invalid element count");
  check_rejected("ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown format");
  check_rejected("ply\nformat ascii 2.0\nend_header\n", "version");
  check_rejected("ply\nelement vertex 1\nend_header\n", "before the format");
  check_rejected(header + "property float x\nend_header\n", "before any element");
  check_rejected(header + "element vertex 1\nproperty float x\nproperty float x\nend_header\n",
                 "duplicate property");
  check_rejected(header + "element vertex 0\nelement vertex 0\nend_header\n", "duplicate element");
  check_rejected(header + "element face 0\nend_header\n", "no vertex element");
  check_rejected(header + "bogus line\nend_header\n", "unknown keyword");
  check_rejected(header +
                     "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 1\nproperty list float int idx\nend_header\n",
                 "list count type");
  check_rejected(header +
                     "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 1\nproperty list uint int idx\nend_header\n" +
                     raw(uint32_t(1u << 30), false),
                 "truncated in a list");
  check_rejected(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 zz\n",
      "invalid number");
  check_rejected(
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1.000 2.000 3.000\n4.000 5.000\n",
      "ends early");
  check_rejected(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3\n4 5 6\n",
      "unexpected data");
  check_rejected(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int i\nend_header\n1 2 3\n-2\n",
      "invalid list length");
  check_rejected("ply\n" + std::string(sh::ply::kMaxHeaderBytes, 'c') + "\n", "missing end_header");
}

TEST_CASE("no truncation or byte flip of a PLY file crashes the reader") {
  const std::string good = two_point_binary_le();
  std::vector<double> xyz;
  std::string error;
  REQUIRE(parse(good, &xyz, &error));
  for (std::size_t n = 0; n < good.size(); ++n) {
    CAPTURE(n);
    CHECK_FALSE(parse(good.substr(0, n), &xyz, &error));
  }
  std::mt19937 rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string mutated = good;
    mutated[rng() % mutated.size()] = static_cast<char>(rng());
    if (parse(mutated, &xyz, &error)) CHECK(xyz.size() % 3 == 0);
  }
}

TEST_CASE("plain text clouds: x y z per line") {
  std::vector<double> xyz;
  std::string error;
  REQUIRE_MESSAGE(parse("x y z intensity\n# a comment\n1 2 3 99\n\n4 5 6\n7\t8\t9 # note\n"
                        "nan -1e2 +3.5\r\n",
                        &xyz, &error),
                  error);
  REQUIRE(xyz.size() == 12);
  CHECK(xyz[3] == 4.0);
  CHECK(xyz[8] == 9.0);
  CHECK(std::isnan(xyz[9]));
  CHECK(xyz[10] == -100.0);
  CHECK(xyz[11] == 3.5);
  CHECK(parse("500000.123456789 4000000.987654321 12\n", &xyz, &error));
  CHECK(xyz[0] == 500000.123456789);
  CHECK(xyz[1] == 4000000.987654321);

  check_rejected("1 2 3\n4 5\n", "line 2");
  check_rejected("1 2 3\n4 five 6\n", "not a number");
  check_rejected("", "no points");
  check_rejected("# only comments\n", "no points");
  check_rejected(std::string("1 2 3\n\0\x01\x02", 9), "binary data");
}

TEST_CASE("read_cloud: files on disk and file errors") {
  TempDir dir("cloud");
  std::vector<double> xyz;
  std::string error;
  write_bytes(dir.file("q.xyz"), "1 2 3\n");
  REQUIRE_MESSAGE(spinhash::host::test::try_read_cloud(dir.file("q.xyz"), &xyz, &error), error);
  CHECK(xyz == std::vector<double>{1, 2, 3});
  CHECK_FALSE(spinhash::host::test::try_read_cloud(dir.file("absent.ply"), &xyz, &error));
  CHECK(error.find("not found") != std::string::npos);
  CHECK_FALSE(spinhash::host::test::try_read_cloud(dir.path().string(), &xyz, &error));
  CHECK(error.find("not a regular file") != std::string::npos);
  write_bytes(dir.file("bad.ply"), "ply\nformat ascii 1.0\n");
  CHECK_FALSE(spinhash::host::test::try_read_cloud(dir.file("bad.ply"), &xyz, &error));
  CHECK(error.find("bad.ply") != std::string::npos);
}

TEST_CASE("poses round trip exactly; malformed poses are rejected") {
  TempDir dir("cloud");
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  pose.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.topRightCorner<3, 1>() = Eigen::Vector3d(500000.1, 4000000.2, 100.3);
  std::string error;
  REQUIRE_MESSAGE(sh::write_pose(dir.file("pose.txt"), pose, &error), error);
  Eigen::Matrix4d back;
  REQUIRE_MESSAGE(sh::read_pose(dir.file("pose.txt"), &back, &error), error);
  CHECK(back == pose);

  const auto rejected = [&dir](const std::string& text) {
    write_bytes(dir.file("bad.txt"), text);
    Eigen::Matrix4d unused;
    std::string why;
    return !sh::read_pose(dir.file("bad.txt"), &unused, &why) && !why.empty();
  };
  CHECK(rejected("1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0\n"));
  CHECK(rejected("1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1 5\n"));
  CHECK(rejected("1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 1 1\n"));
  CHECK(rejected("1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 x\n"));
  CHECK(rejected("nan 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"));
  CHECK(rejected(std::string(10000, ' ')));
  Eigen::Matrix4d unused;
  CHECK_FALSE(sh::read_pose(dir.file("missing.txt"), &unused, &error));
}
