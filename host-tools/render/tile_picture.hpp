// A top-down picture of a lidar tile with what was found in it: points
// shaded by height, each detected object's footprint outlined and labelled
// (model and confidence, or what it is), its points coloured by the answer.
// North (+y) is up. A person should see at a glance what was found.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

enum class BoxStyle : uint8_t {
  kConfident,   // a vehicle recognised with confidence: green
  kUnsure,      // a vehicle candidate without a confident answer: orange
  kNotVehicle,  // too large, too small, not vehicle-shaped: blue
};

struct PictureBox {
  double center[2] = {0, 0};  // x, y in the cloud's frame
  double length = 0.0, width = 0.0;
  double heading_deg = 0.0;  // of the length axis, from +x towards +y
  std::string label;
  BoxStyle style = BoxStyle::kUnsure;
};

constexpr uint32_t kPictureSide = 1000;             // pixels along the tile's longer side
constexpr double kPictureMinMetresPerPixel = 0.02;  // small clouds are not blown up further
constexpr double kPicturePointSpacing = 0.1;        // m: airborne point spacing a dot covers

// Writes the picture as PNG; false with *error for an empty cloud or a write failure.
bool write_tile_picture(const std::string& path, const std::vector<double>& xyz,
                        const std::vector<PictureBox>& boxes, const std::string& title, std::string* error);

}  // namespace spinhash::host
