#include "cloud/metric_source.hpp"

#include <algorithm>

#include "cloud/cloud_error.hpp"
#include "cloud/crs_match.hpp"
#include "cloud/crs_resolve.hpp"
#include "cloud/crs_units.hpp"

namespace spinhash::host {
namespace {

void set_scale(const AxisUnits& u, double* s) {
  s[0] = s[1] = u.horizontal;
  s[2] = u.vertical;
}

void add_units(const AxisUnits& u, std::vector<std::string>* notes) {
  for (const std::string& m : u.messages()) notes->push_back("units: " + m);
}

}  // namespace

ToMetres::ToMetres(const AxisUnits& units) {
  work_.units = units;
  set_scale(units, scale_);
}

ToMetres::ToMetres(const std::string& name, const Crs& declared, const WorkCrs& work) {
  const Crs file = declared.resolved ? declared : resolved(declared);
  for (const std::string& w : file.warnings) notes_.push_back("CRS: " + w);
  if (work.crs.known() && work.crs.units.geographic)
    throw CloudError("the CRS to work in, " + work.crs.describe() +
                     ", is in degrees: name a projected CRS (metres or feet)");
  if (!work.crs.known()) {  // the file is its own work CRS
    if (file.units.geographic)
      throw CloudError(name + ": its CRS " + file.describe() + " is geographic: " + file.units.describe());
    work_ = file;
    set_scale(file.units, scale_);
    add_units(file.units, &notes_);
  } else if (!file.known()) {
    work_ = work.crs;
    set_scale(work.crs.units, scale_);
    notes_.push_back("CRS: declares no CRS: taken to be in " + work.crs.describe());
    add_units(work.crs.units, &notes_);
  } else if (same_crs(file, work.crs)) {
    work_ = work.crs;
    set_scale(file.units, scale_);  // the same plane; its heights may come in another unit
    add_units(file.units, &notes_);
  } else if (work.named) {
    work_ = work.crs;
    transform_ = std::make_unique<CrsTransform>(file.proj_definition(), work.crs.proj_definition());
    scale_[0] = scale_[1] = work.crs.units.horizontal;
    scale_[2] = file.units.vertical;
    notes_.push_back("CRS: x y reprojected from " + file.describe() + " to " + work.crs.describe() +
                     "; z in " + file.units.vertical_name + ", not transformed");
  } else {
    throw CloudError(name + ": its CRS " + file.describe() + " is not " + work.crs.describe() +
                     ", the other tiles' (reproject it, or name a CRS to work in: --work-crs EPSG:n)");
  }
}

void ToMetres::apply(double* xyz, size_t points) const {
  if (transform_) transform_->apply(xyz, points);
  if (scale_[0] == 1.0 && scale_[1] == 1.0 && scale_[2] == 1.0) return;
  for (size_t i = 0; i < points; ++i)
    for (int a = 0; a < 3; ++a) xyz[3 * i + a] *= scale_[a];
}

void ToMetres::bounds(const double min[3], const double max[3], double out_min[3], double out_max[3]) const {
  std::copy(min, min + 3, out_min);
  std::copy(max, max + 3, out_max);
  if (transform_ && !transform_->bounds(min, max, out_min, out_max))
    throw CloudError("PROJ cannot reproject the tile's bounds to " + work_.describe());
  for (int a = 0; a < 3; ++a) {
    out_min[a] *= scale_[a];
    out_max[a] *= scale_[a];
  }
}

void scale_to_metres(const AxisUnits& units, double* xyz, size_t points) {
  ToMetres(units).apply(xyz, points);
}

void scale_to_file_units(const AxisUnits& units, double* xyz) {
  xyz[0] /= units.horizontal;
  xyz[1] /= units.horizontal;
  xyz[2] /= units.vertical;
}

MetricSource::MetricSource(std::unique_ptr<PointSource> inner, const std::string& name, const WorkCrs& work)
    : owned_(std::move(inner)),
      inner_(*owned_),
      to_metres_(name, owned_->header().crs, work),
      header_(inner_.header()) {
  if (header_.bounds_known)
    to_metres_.bounds(inner_.header().min, inner_.header().max, header_.min, header_.max);
}

MetricSource::MetricSource(PointSource& inner, const AxisUnits& units)
    : inner_(inner), to_metres_(units), header_(inner.header()) {
  if (header_.bounds_known)
    to_metres_.bounds(inner_.header().min, inner_.header().max, header_.min, header_.max);
}

size_t MetricSource::read(double* xyz, size_t max_points) {
  const size_t got = inner_.read(xyz, max_points);
  to_metres_.apply(xyz, got);
  return got;
}

std::unique_ptr<MetricSource> open_metric_source(const std::string& path, const WorkCrs& work,
                                                 const PointFilter& filter) {
  std::unique_ptr<PointSource> inner = open_point_source(path, filter);
  return std::make_unique<MetricSource>(std::move(inner), cloud_name(path), work);
}

}  // namespace spinhash::host
