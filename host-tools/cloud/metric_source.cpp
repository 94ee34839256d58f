#include "cloud/metric_source.hpp"

namespace spinhash::host {
namespace {

// m per unit of x, y and z.
void scales(const AxisUnits& u, double* s) {
  s[0] = s[1] = u.horizontal;
  s[2] = u.vertical;
}

}  // namespace

void scale_to_metres(const AxisUnits& units, double* xyz, size_t points) {
  double s[3];
  scales(units, s);
  if (s[0] == 1.0 && s[2] == 1.0) return;
  for (size_t i = 0; i < points; ++i)
    for (int a = 0; a < 3; ++a) xyz[3 * i + a] *= s[a];
}

void scale_to_file_units(const AxisUnits& units, double* xyz) {
  double s[3];
  scales(units, s);
  for (int a = 0; a < 3; ++a) xyz[a] /= s[a];
}

MetricSource::MetricSource(PointSource& inner, const AxisUnits& units)
    : inner_(inner), units_(units), header_(inner.header()) {
  scale_to_metres(units_, header_.min, 1);
  scale_to_metres(units_, header_.max, 1);
}

size_t MetricSource::read(double* xyz, size_t max_points) {
  const size_t got = inner_.read(xyz, max_points);
  scale_to_metres(units_, xyz, got);
  return got;
}

}  // namespace spinhash::host
