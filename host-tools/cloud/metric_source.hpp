// The reading door in metres: a file's points handed out as metres of the
// CRS the tools work in, whatever the file's units, so that the scene's
// gates, the recognizer's radii and the database's models (all in metres)
// see real sizes. x and y times the CRS's horizontal unit, z times its
// vertical unit (cloud/crs_units.hpp); or, for a file in another CRS than
// the one the user names to work in (--work-crs), x y reprojected through
// PROJ first. Header bounds come the same way. Outputs go back to the work
// CRS's units (units()): pipeline/object_units.hpp.
//
// Which CRS is worked in: the one the user names; else the survey's (its
// tiles must share it) or the file's own. A file in degrees is refused
// unless the user names a projected CRS; a file without a CRS is taken to
// be in the work CRS (or, alone, in metres), and notes() says so.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cloud/crs.hpp"
#include "cloud/crs_transform.hpp"
#include "cloud/point_source.hpp"

namespace spinhash::host {

struct WorkCrs {
  Crs crs;             // resolved; unknown: each file's own
  bool named = false;  // the user named it: files in other CRSs are reprojected into it
};

// How one file's coordinates become metres of the work CRS.
class ToMetres {
 public:
  // Throws CloudError ("<name>: ...") for a file in degrees without a
  // named work CRS, or in another CRS than the work CRS when it is not
  // named (a survey's catalogue refuses such tiles first).
  ToMetres(const std::string& name, const Crs& file, const WorkCrs& work);
  // Scaling alone, by known units.
  explicit ToMetres(const AxisUnits& units);

  void apply(double* xyz, size_t points) const;
  // The header's bounds in metres (reprojected boxes hold the whole tile).
  void bounds(const double min[3], const double max[3], double out_min[3], double out_max[3]) const;
  // The CRS worked in (the file's own when no other is given) and its units.
  const Crs& work_crs() const { return work_; }
  const AxisUnits& units() const { return work_.units; }
  bool reprojected() const { return transform_ != nullptr; }
  // What was assumed: the file's CRS warnings, its units, a reprojection.
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  Crs work_;
  double scale_[3] = {1.0, 1.0, 1.0};  // m per unit of the file (after reprojection: of the work CRS)
  std::unique_ptr<CrsTransform> transform_;
  std::vector<std::string> notes_;
};

// points x y z triples from units to metres, in place.
void scale_to_metres(const AxisUnits& units, double* xyz, size_t points);
// One point from metres back to the units, in place.
void scale_to_file_units(const AxisUnits& units, double* xyz);

class MetricSource final : public PointSource {
 public:
  // header().crs stays the file's; its bounds are in metres.
  MetricSource(std::unique_ptr<PointSource> inner, const std::string& name, const WorkCrs& work);
  // Over a source the caller keeps, scaled by known units.
  MetricSource(PointSource& inner, const AxisUnits& units);
  const CloudHeader& header() const override { return header_; }
  size_t read(double* xyz, size_t max_points) override;
  uint64_t points_noise() const override { return inner_.points_noise(); }
  const ToMetres& to_metres() const { return to_metres_; }

 private:
  std::unique_ptr<PointSource> owned_;
  PointSource& inner_;
  ToMetres to_metres_;
  CloudHeader header_;
};

// open_point_source(path, filter) in metres of the work CRS. Throws CloudError.
std::unique_ptr<MetricSource> open_metric_source(const std::string& path, const WorkCrs& work = {},
                                                 const PointFilter& filter = {});

}  // namespace spinhash::host
