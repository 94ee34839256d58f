// A flight line for the streaming scene stage: a strip of `length` m along
// +y built of square segments (`segment.size` m, each a tile of the scene
// simulator with its own seed: vehicles alone and in parked rows, trees,
// buildings, walls, crates), the terrain rising and falling along the track
// at `segment.slope_deg` in turn so the segments meet without a step. Each
// point gets the GPS time at which a sensor flying the line at `speed` m/s
// would see it (its view's along-track position), and the points come out
// in that order: scan order, lagging the furthest point seen by at most
// `max_lag` m (the views look fore, aft and across).
#pragma once

#include "scan/scene_simulator.hpp"

#include <cstdint>
#include <vector>

namespace spinhash::host {

constexpr double kMaxFlightLineLength = 20000.0;  // m
constexpr uint32_t kMaxFlightLineSegments = 400;

struct FlightLineOptions {
  SceneOptions segment;    // one segment; its seed is the line's, the offset the line's start
  double length = 1000.0;  // m along track
  double speed = 60.0;     // m/s: the GPS time's scale
};

struct FlightLineScan {
  SceneScan scan;                // every segment's points in scan order, truth of every object
  std::vector<double> gps_time;  // s, per point, non-decreasing
  double max_lag = 0.0;          // m: the largest distance a point arrives behind the furthest before it
  uint32_t segments = 0;
};

std::string validate_flight_line_options(const FlightLineOptions& options);

FlightLineScan simulate_flight_line(const std::vector<Mesh>& vehicles, const std::vector<Mesh>& unknown,
                                    const FlightLineOptions& options);

}  // namespace spinhash::host
