#include "mesh/pie_reader.hpp"

#include <doctest/doctest.h>

#include <sstream>

namespace sh = spinhash::host;

namespace {

bool parse(const std::string& text, sh::Mesh* m, sh::PieInfo* info, std::string* error) {
  std::istringstream in(text);
  return sh::parse_pie(in, m, info, error);
}

// PIE 2: integer points, a quad and a triangle, unknown sections to skip.
constexpr const char* kPie2 =
    "PIE 2\r\nTYPE 200\r\nTEXTURE 0 page-14.png 256 256\r\nLEVELS 1\r\nLEVEL 1\r\nPOINTS 5 \r\n"
    "\t0 0 0 \r\n\t10 0 0 \r\n\t10 10 0 \r\n\t0 10 0 \r\n\t5 5 8\r\n"
    "POLYGONS 2\r\n\t200 4 0 1 2 3 0 0 1 0 1 1 0 1\r\n\t4200 3 0 1 4 8 1 16 16 0 0 1 0 1 1\r\n"
    "CONNECTORS 1\r\n\t0 10 23\r\n";

// PIE 3: float points, two levels whose indices restart at 0.
constexpr const char* kPie3 =
    "PIE 3\nTYPE 10200\nTEXTURE 0 page.png 0 0\nLEVELS 2\nLEVEL 1\nPOINTS 3\n"
    "\t0.5 0 0\n\t1.5 0 0\n\t0.5 1.25 0\nPOLYGONS 1\n\t200 3 0 1 2 0 0 1 0 0 1\n"
    "ANIMOBJECT 80 0 1\n\t0 0 0 0  0 0 0  1 1 1\n"
    "LEVEL 2\nPOINTS 3\n\t0 0 5\n\t1 0 5\n\t0 1 5\nPOLYGONS 1\n\t200 3 2 1 0 0 0 1 0 0 1\n";

}  // namespace

TEST_CASE("PIE 2 with CRLF: quad fanned, texture-animated polygon read, other sections skipped") {
  sh::Mesh m;
  sh::PieInfo info;
  std::string error;
  REQUIRE_MESSAGE(parse(kPie2, &m, &info, &error), error);
  CHECK(info.version == 2);
  CHECK(info.levels == 1);
  CHECK(info.polygons == 2);
  CHECK(m.vertex_count() == 5);
  CHECK(m.triangle_count() == 3);  // quad -> 2, triangle -> 1
  CHECK(m.triangles[6] == 0u);
  CHECK(m.triangles[8] == 4u);
}

TEST_CASE("PIE 3 levels are separate parts with their own indices") {
  sh::Mesh m;
  sh::PieInfo info;
  std::string error;
  REQUIRE_MESSAGE(parse(kPie3, &m, &info, &error), error);
  CHECK(info.version == 3);
  CHECK(info.levels == 2);
  REQUIRE(m.triangle_count() == 2);
  CHECK(m.triangles[3] == 5u);  // level 2's index 2 -> vertex 3 + 2
  CHECK(m.vertex(2).y() == doctest::Approx(1.25));
}

TEST_CASE("PIE 4 header accepted; malformed files refused with a reason") {
  sh::Mesh m;
  sh::PieInfo info;
  std::string error;
  CHECK(parse("PIE 4\nLEVELS 1\nLEVEL 1\nPOINTS 3\n0 0 0\n1 0 0\n0 1 0\nPOLYGONS 1\n200 3 0 1 2\n", &m, &info,
              &error));
  CHECK_FALSE(parse("PIE 5\n", &m, &info, &error));
  CHECK_FALSE(parse("OBJ\n", &m, &info, &error));
  CHECK_FALSE(
      parse("PIE 3\nLEVEL 1\nPOINTS 3\n0 0 0\n1 0 0\nPOLYGONS 0\n", &m, &info, &error));  // 2 of 3 points
  CHECK_FALSE(
      parse("PIE 3\nLEVEL 1\nPOINTS 3\n0 0 0\n1 0 0\n0 1 0\nPOLYGONS 1\n200 3 0 1 3\n", &m, &info, &error));
  CHECK(error.find("out of range") != std::string::npos);
  CHECK_FALSE(parse("PIE 3\nLEVEL 1\nPOINTS 1\n0 nan 0\n", &m, &info, &error));
  CHECK_FALSE(parse("PIE 3\nLEVEL 1\nPOINTS 3\n0 0 0\n1 0 0\n0 1 0\n", &m, &info, &error));  // no polygons
}

TEST_CASE("PIE to metres is a proper rotation scaled to metres, y up becomes z up") {
  Eigen::Matrix4d t = sh::pie_to_metres();
  CHECK(t.topLeftCorner<3, 3>().determinant() > 0.0);
  Eigen::Vector4d up = t * Eigen::Vector4d(0, 1, 0, 1);
  CHECK(up.z() == doctest::Approx(sh::kPieMetresPerUnit));
}
