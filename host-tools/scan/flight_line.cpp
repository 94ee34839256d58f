#include "scan/flight_line.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace spinhash::host {
namespace {

constexpr uint64_t kSegmentSeedStride = 0x9E3779B97F4A7C15ull;  // decorrelates the segments' seeds
constexpr double kMinSpeed = 1.0, kMaxSpeed = 500.0;            // m/s
constexpr double kRisingDeg = 90.0, kFallingDeg = 270.0;        // the plane's direction, along +y or -y
constexpr double kPointInterval = 1e-7;  // s between a view's consecutive points: keeps the order

// GPS time of each point of one segment: its view's along-track position
// over the speed, plus its index within the view.
void segment_times(const SceneScan& s, double start_y, double speed, std::vector<double>* t) {
  size_t i = 0;
  for (size_t v = 0; v < s.view_points.size(); ++v) {
    const double t0 = (s.viewpoints[v].y() - start_y) / speed;
    for (uint32_t k = 0; k < s.view_points[v]; ++k, ++i) t->push_back(t0 + kPointInterval * k);
  }
}

void append_segment(SceneScan&& seg, FlightLineScan* out) {
  SceneScan& all = out->scan;
  const int32_t base = static_cast<int32_t>(all.objects.size());
  all.xyz.insert(all.xyz.end(), seg.xyz.begin(), seg.xyz.end());
  all.classification.insert(all.classification.end(), seg.classification.begin(), seg.classification.end());
  for (int32_t o : seg.object) all.object.push_back(o < 0 ? o : o + base);
  all.objects.insert(all.objects.end(), seg.objects.begin(), seg.objects.end());
  all.viewpoints.insert(all.viewpoints.end(), seg.viewpoints.begin(), seg.viewpoints.end());
  all.view_points.insert(all.view_points.end(), seg.view_points.begin(), seg.view_points.end());
  all.rays += seg.rays;
}

// Puts the points in GPS-time order and measures the along-track lag.
void scan_order(FlightLineScan* line) {
  SceneScan& s = line->scan;
  const size_t n = line->gps_time.size();
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return line->gps_time[a] < line->gps_time[b]; });
  std::vector<double> xyz(3 * n), time(n);
  std::vector<uint8_t> cls(n);
  std::vector<int32_t> obj(n);
  double furthest = -INFINITY;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = order[k];
    std::copy(s.xyz.begin() + 3 * i, s.xyz.begin() + 3 * i + 3, xyz.begin() + 3 * k);
    time[k] = line->gps_time[i];
    cls[k] = s.classification[i];
    obj[k] = s.object[i];
    furthest = std::max(furthest, xyz[3 * k + 1]);
    line->max_lag = std::max(line->max_lag, furthest - xyz[3 * k + 1]);
  }
  s.xyz = std::move(xyz);
  s.classification = std::move(cls);
  s.object = std::move(obj);
  line->gps_time = std::move(time);
}

}  // namespace

std::string validate_flight_line_options(const FlightLineOptions& o) {
  std::string e = validate_scene_options(o.segment);
  if (!e.empty()) return e;
  if (!(o.length >= o.segment.size && o.length <= kMaxFlightLineLength))
    return "line length must be in [segment size, " + std::to_string(static_cast<int>(kMaxFlightLineLength)) +
           "] m";
  if (std::ceil(o.length / o.segment.size) > kMaxFlightLineSegments)
    return "at most " + std::to_string(kMaxFlightLineSegments) + " segments: use a larger --size";
  if (!(o.speed >= kMinSpeed && o.speed <= kMaxSpeed)) return "speed must be in [1, 500] m/s";
  return {};
}

FlightLineScan simulate_flight_line(const std::vector<Mesh>& vehicles, const std::vector<Mesh>& unknown,
                                    const FlightLineOptions& o) {
  FlightLineScan out;
  out.scan.error = validate_flight_line_options(o);
  if (!out.scan.ok()) return out;
  const uint32_t segments = static_cast<uint32_t>(std::ceil(o.length / o.segment.size - 1e-9));
  const double start_y = o.segment.offset[1];
  for (uint32_t i = 0; i < segments; ++i) {
    SceneOptions s = o.segment;
    s.seed = o.segment.seed + kSegmentSeedStride * (i + 1);
    s.slope_azimuth_deg = i % 2 == 0 ? kRisingDeg : kFallingDeg;  // ridges and valleys, no steps
    s.offset[1] = start_y + (i + 0.5) * o.segment.size;
    SceneScan seg = simulate_scene(vehicles, unknown, s);
    if (!seg.ok()) {
      out.scan = SceneScan{};
      out.scan.error = "segment " + std::to_string(i + 1) + ": " + seg.error;
      return out;
    }
    segment_times(seg, start_y, o.speed, &out.gps_time);
    append_segment(std::move(seg), &out);
  }
  out.segments = segments;
  scan_order(&out);
  return out;
}

}  // namespace spinhash::host
