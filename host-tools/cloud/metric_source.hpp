// A PointSource in metres: x and y times the CRS's horizontal unit, z times
// its vertical one (cloud/crs_units.hpp), header bounds included. Metres
// pass through untouched; degrees too (nothing scales them to metres).
#pragma once

#include "cloud/crs_units.hpp"
#include "cloud/point_source.hpp"

namespace spinhash::host {

// points x y z triples from the file's units to metres, in place.
void scale_to_metres(const AxisUnits& units, double* xyz, size_t points);
// One point from metres back to the file's units, in place.
void scale_to_file_units(const AxisUnits& units, double* xyz);

class MetricSource : public PointSource {
 public:
  MetricSource(PointSource& inner, const AxisUnits& units);
  const CloudHeader& header() const override { return header_; }
  size_t read(double* xyz, size_t max_points) override;

 private:
  PointSource& inner_;
  AxisUnits units_;
  CloudHeader header_;
};

}  // namespace spinhash::host
