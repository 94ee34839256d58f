// The calibration's clutter scans (host-tools/calib/calibration_scans): every
// kind has its own name, scans to points and scans the same from the same
// draw; the vehicle-sized kinds are scanned only when the build asks.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "calib/calibration_scans.hpp"
#include "spinhash/blob_format.hpp"

using namespace spinhash;

namespace {

calib::ScanDraw plain_draw(uint64_t seed) {
  calib::ScanDraw d;
  d.seed = seed;
  d.spacing = 0.25;  // a sparse survey's
  d.noise = 0.02;
  d.views = 3;
  d.elevation_deg = 50.0;
  d.ground = false;
  return d;
}

}  // namespace

TEST_CASE("calibration clutter: every kind is named and scans to points") {
  std::vector<std::string> names;
  for (uint32_t k = 0; k < calib::kClutterKinds; ++k) {
    const auto kind = static_cast<calib::ClutterKind>(k);
    names.push_back(calib::clutter_name(kind));
    std::vector<double> xyz;
    std::string error;
    REQUIRE_MESSAGE(calib::scan_clutter(kind, plain_draw(11 + k), &xyz, &error), error);
    CHECK_MESSAGE(xyz.size() >= 3 * 20, names.back());
    CHECK(xyz.size() % 3 == 0);
  }
  std::vector<std::string> unique = names;
  std::sort(unique.begin(), unique.end());
  CHECK(std::unique(unique.begin(), unique.end()) == unique.end());
}

TEST_CASE("calibration clutter: the ground stays only when the draw keeps it") {
  for (uint32_t k = 0; k < calib::kClutterKinds; ++k) {
    const auto kind = static_cast<calib::ClutterKind>(k);
    calib::ScanDraw d = plain_draw(7);
    std::vector<double> bare, grounded;
    std::string error;
    REQUIRE(calib::scan_clutter(kind, d, &bare, &error));
    d.ground = true;
    REQUIRE(calib::scan_clutter(kind, d, &grounded, &error));
    CHECK_MESSAGE(grounded.size() > bare.size(), calib::clutter_name(kind));
  }
}

TEST_CASE("calibration clutter: the same draw scans to the same points") {
  for (uint32_t k = 0; k < calib::kClutterKinds; ++k) {
    const auto kind = static_cast<calib::ClutterKind>(k);
    std::vector<double> a, b;
    std::string error;
    REQUIRE(calib::scan_clutter(kind, plain_draw(3), &a, &error));
    REQUIRE(calib::scan_clutter(kind, plain_draw(3), &b, &error));
    CHECK(a == b);
  }
}

TEST_CASE("calibration clutter: the tiles' four kinds first, the vehicle-sized ones only when asked") {
  CHECK(calib::clutter_kinds_scanned(blob::kClutterTiles) == 4u);
  CHECK(calib::clutter_kinds_scanned(blob::kClutterVehicleSized) == calib::kClutterKinds);
  const char* tiles[] = {"tree", "wall", "crate", "building"};
  for (uint32_t k = 0; k < 4u; ++k)
    CHECK(std::string(calib::clutter_name(static_cast<calib::ClutterKind>(k))) == tiles[k]);
  CHECK(std::string(calib::calibration_clutter_word(blob::kClutterTiles)) == "tiles");
  CHECK(std::string(calib::calibration_clutter_word(blob::kClutterVehicleSized)) == "vehicle-sized");
  CHECK(
      std::string(calib::calibration_clutter_kinds(blob::kClutterVehicleSized)).find("freight containers") !=
      std::string::npos);
  CHECK(std::string(calib::calibration_clutter_kinds(blob::kClutterTiles)).find("containers") ==
        std::string::npos);
}
