// Angle constants of the host tools (simulators, pictures, experiments), in
// double; the core has its own float deg_to_rad (firmware-lib/util).
#pragma once

namespace spinhash::host {

constexpr double kPi = 3.141592653589793;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kRadToDeg = 180.0 / kPi;

}  // namespace spinhash::host
