// The stream frame and the window lattice: square cores of edge `core` tile
// the (s, t) plane, each window's terrain sees its core plus `margin` on
// every side and its objects the core plus `object_margin`, and an object
// belongs to the window whose core holds its centre (the ownership rule of
// scene_ownership.hpp, each core an owned area).
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

#include "spinhash/scene_ownership.hpp"

namespace spinhash {

// Beyond every coordinate: the empty box's bounds.
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// A point with three finite coordinates (the rest is counted, never used).
inline bool finite_xyz(const double* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Every scene path takes the frame's coordinates to a 1 mm lattice: the
// stream buffers them as 32-bit steps (12 B a point, half the doubles), and
// the tile API snaps the same way, so both see the same coordinates. Lidar
// carries millimetres at best (LAS stores 1 mm or 1 cm steps); within
// kLatticeReach of the origin (int32 millimetres).
constexpr double kLatticeUnit = 1e-3;        // m
constexpr double kLatticeReach = 2000000.0;  // m
inline bool within_lattice(const double* stz) {
  return std::fabs(stz[0]) < kLatticeReach && std::fabs(stz[1]) < kLatticeReach &&
         std::fabs(stz[2]) < kLatticeReach;
}
// The nearest step, halves away from zero (llround's rule, without its libm
// call: this runs per point), for |v| < kLatticeReach: the truncation and
// the fraction it left (exact), one step more where that is half or more.
inline int32_t lattice_steps(double v) {
  const double q = v / kLatticeUnit;
  const auto k = static_cast<int64_t>(q);
  const double fraction = q - static_cast<double>(k);
  return static_cast<int32_t>(k + (fraction >= 0.5 ? 1 : 0) - (fraction <= -0.5 ? 1 : 0));
}
inline double from_steps(int32_t k) { return static_cast<double>(k) * kLatticeUnit; }
inline double on_lattice(double v) { return from_steps(lattice_steps(v)); }

// The least step k with from_steps(k) >= v (from_steps rises with k), so
// that `from_steps(k) >= v` is `k >= first_step_from(v)` and
// `from_steps(k) < v` is `k < first_step_from(v)` for every int32 k: the
// buffer's scans compare the steps, not the coordinates. v: not NaN.
inline int64_t first_step_from(double v) {
  constexpr int64_t kLow = INT32_MIN, kHigh = INT32_MAX;
  if (v <= static_cast<double>(kLow) * kLatticeUnit) return kLow;
  if (v > static_cast<double>(kHigh) * kLatticeUnit) return kHigh + 1;
  auto k = static_cast<int64_t>(std::ceil(v / kLatticeUnit));  // within a step of the answer
  for (int i = 0; i < 2 && k > kLow && static_cast<double>(k - 1) * kLatticeUnit >= v; ++i) --k;
  for (int i = 0; i < 2 && static_cast<double>(k) * kLatticeUnit < v; ++i) ++k;
  return k;
}

// s along track, t across (counter-clockwise from s), z up, from an origin.
struct StreamFrame {
  double origin[3] = {0, 0, 0};
  double ax = 1.0, ay = 0.0;  // along-track unit vector in xy

  void set_heading(double heading_deg) {
    const double r = heading_deg * (3.14159265358979323846 / 180.0);
    ax = std::cos(r);
    ay = std::sin(r);
  }
  // World xyz -> (s, t, z - origin z).
  void to_frame(const double* xyz, double* stz) const {
    const double dx = xyz[0] - origin[0], dy = xyz[1] - origin[1];
    stz[0] = dx * ax + dy * ay;
    stz[1] = -dx * ay + dy * ax;
    stz[2] = xyz[2] - origin[2];
  }
  // The same on the 1 mm lattice (the points every window sees).
  void to_lattice(const double* xyz, double* stz) const {
    to_frame(xyz, stz);
    for (int a = 0; a < 3; ++a) stz[a] = on_lattice(stz[a]);
  }
  // A frame offset (ds, dt) -> the world xy offset it spans.
  void offset_to_world(double ds, double dt, double* dx, double* dy) const {
    *dx = ds * ax - dt * ay;
    *dy = ds * ay + dt * ax;
  }
};

// A half-open rectangle [s0, s1) x [t0, t1) of the frame.
struct FrameRect {
  double s0 = 0, s1 = 0, t0 = 0, t1 = 0;
  bool holds(double s, double t) const { return s >= s0 && s < s1 && t >= t0 && t < t1; }
};

// The same rectangle on the steps: holds(k) is FrameRect::holds of the
// point from_steps(k) (first_step_from).
struct StepRect {
  int64_t s0, s1, t0, t1;
  explicit StepRect(const FrameRect& r)
      : s0(first_step_from(r.s0)),
        s1(first_step_from(r.s1)),
        t0(first_step_from(r.t0)),
        t1(first_step_from(r.t1)) {}
  bool holds(const int32_t* k) const { return k[0] >= s0 && k[0] < s1 && k[1] >= t0 && k[1] < t1; }
};

struct WindowLattice {
  double core = 32.0;                   // m
  double margin = 40.0;                 // m: the terrain's
  double object_margin = 10.0;          // m: the objects' (at most margin)
  double own_min = 0.0, own_max = 0.0;  // across track, owned

  int64_t row_of(double s) const { return static_cast<int64_t>(std::floor(s / core)); }
  uint32_t columns() const {
    const double c = std::ceil((own_max - own_min) / core);
    return c > 0.0 ? static_cast<uint32_t>(c) : 0u;
  }
  FrameRect core_rect(int64_t k, uint32_t j) const {
    FrameRect r;
    r.s0 = static_cast<double>(k) * core;
    r.s1 = r.s0 + core;
    r.t0 = own_min + static_cast<double>(j) * core;
    r.t1 = r.t0 + core < own_max ? r.t0 + core : own_max;
    return r;
  }
  // The core as the area that owns the objects whose centre it holds.
  OwnedArea owned_area(int64_t k, uint32_t j) const {
    const FrameRect r = core_rect(k, j);
    OwnedArea a;
    a.min[0] = r.s0;
    a.max[0] = r.s1;
    a.min[1] = r.t0;
    a.max[1] = r.t1;
    return a;
  }
  FrameRect seen_rect(int64_t k, uint32_t j) const { return grown(core_rect(k, j), margin); }
  FrameRect gather_rect(int64_t k, uint32_t j) const { return grown(core_rect(k, j), object_margin); }

 private:
  static FrameRect grown(FrameRect r, double by) {
    r.s0 -= by;
    r.s1 += by;
    r.t0 -= by;
    r.t1 += by;
    return r;
  }
};

}  // namespace spinhash
