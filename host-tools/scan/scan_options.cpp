#include "scan/scan_simulator.hpp"

#include <cmath>

namespace spinhash::host {
namespace {

constexpr uint32_t kModelViews = 8;
constexpr uint32_t kQueryViews = 3;
constexpr double kPaperElevationDeg = 45.0;
constexpr double kPaperAzimuthStepDeg = 45.0;
constexpr double kMaxElevationDeg = 90.0;
constexpr double kMaxNoiseSigma = 10.0;  // m: beyond this a scan is meaningless

}  // namespace

ScanOptions model_scan_options() {
  ScanOptions options;
  options.views = kModelViews;
  options.elevation_deg = kPaperElevationDeg;
  options.azimuth_start_deg = 0.0;
  options.azimuth_step_deg = kPaperAzimuthStepDeg;
  options.noise_sigma = 0.0;
  return options;
}

ScanOptions query_scan_options(double noise_sigma, uint64_t seed) {
  ScanOptions options;
  options.views = kQueryViews;
  options.elevation_deg = kPaperElevationDeg;
  options.azimuth_step_deg = kPaperAzimuthStepDeg;
  options.noise_sigma = noise_sigma;
  options.seed = seed;
  return options;
}

std::string validate_scan_options(const ScanOptions& o) {
  if (o.views == 0 || o.views > kMaxScanViews) {
    return "views must be in 1.." + std::to_string(kMaxScanViews);
  }
  if (!(o.elevation_deg >= 0.0 && o.elevation_deg <= kMaxElevationDeg)) {
    return "elevation must be in [0, 90] degrees";
  }
  if (std::isinf(o.azimuth_start_deg)) return "azimuth start must be finite (or NaN: random)";
  if (!std::isfinite(o.azimuth_step_deg)) return "azimuth step must be finite";
  if (!(o.noise_sigma >= 0.0 && o.noise_sigma <= kMaxNoiseSigma)) {
    return "noise sigma must be in [0, 10] m";
  }
  if (!(o.point_spacing > 0.0) || !std::isfinite(o.point_spacing)) {
    return "point spacing must be a positive number of metres";
  }
  if (!(o.occlusion >= 0.0 && o.occlusion < 1.0)) return "occlusion must be in [0, 1)";
  if (!(o.ground_slope_deg >= 0.0 && o.ground_slope_deg <= kMaxGroundSlopeDeg))
    return "ground slope must be in [0, " + std::to_string(static_cast<int>(kMaxGroundSlopeDeg)) +
           "] degrees";
  for (double v : o.offset) {
    if (!std::isfinite(v)) return "offset must be finite";
  }
  return {};
}

}  // namespace spinhash::host
