// Reprojection of x y from one CRS to another through PROJ, for files in
// another CRS than the one the user works in (--work-crs): easting first,
// northing second on both sides, whatever the CRSs' axis order. z is not
// transformed (heights stay in the file's vertical unit: the scene measures
// them from the local ground, so a vertical datum does not matter).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace spinhash::host {

class CrsTransform {
 public:
  // Throws CloudError when PROJ finds no transformation.
  CrsTransform(const std::string& from_definition, const std::string& to_definition);
  ~CrsTransform();
  CrsTransform(const CrsTransform&) = delete;
  CrsTransform& operator=(const CrsTransform&) = delete;

  // x y of n points (stride 3 doubles) in place; a point PROJ cannot
  // transform becomes NaN (the scene drops and counts it).
  void apply(double* xyz, size_t n) const;
  // The box that holds [min, max] once transformed (x, y; edges densified).
  // False when PROJ cannot transform it.
  bool bounds(const double min[2], const double max[2], double out_min[2], double out_max[2]) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace spinhash::host
