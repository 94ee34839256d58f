#include "survey/catalogue.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "cloud/crs_match.hpp"

namespace spinhash::survey {
namespace {

namespace fs = std::filesystem;

bool cloud_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".las" || ext == ".laz" || ext == ".ply" || ext == ".txt" || ext == ".xyz" || ext == ".csv";
}

// Bounds from the points (in metres of the work CRS), for headers without
// them (PLY, text).
void bounds_from_points(CatalogueTile& t, const host::WorkCrs& work) {
  constexpr size_t kChunk = host::kDefaultChunkPoints;
  std::unique_ptr<host::PointSource> source = host::open_metric_source(t.path, work);
  std::vector<double> xyz(3 * kChunk);
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  uint64_t n = 0;
  for (size_t got; (got = source->read(xyz.data(), kChunk)) > 0; n += got)
    for (size_t i = 0; i < got; ++i)
      for (int a = 0; a < 3; ++a)
        if (std::isfinite(xyz[3 * i + a]))
          lo[a] = std::min(lo[a], xyz[3 * i + a]), hi[a] = std::max(hi[a], xyz[3 * i + a]);
  if (!(lo[0] <= hi[0] && lo[1] <= hi[1])) throw host::CloudError(t.path + ": no finite point");
  std::copy(lo, lo + 3, t.header.min);
  std::copy(hi, hi + 3, t.header.max);
  t.header.bounds_known = true;
  t.header.count_known = true;
  t.header.point_count = n;
  t.bounds_from_points = true;
}

// The header's bounds in metres of the work CRS.
void metric_bounds(CatalogueTile& t, const host::WorkCrs& work) {
  if (!t.header.bounds_known) return bounds_from_points(t, work);
  const host::ToMetres to_metres(t.name, t.header.crs, work);
  double lo[3], hi[3];
  to_metres.bounds(t.header.min, t.header.max, lo, hi);
  std::copy(lo, lo + 3, t.header.min);
  std::copy(hi, hi + 3, t.header.max);
}

std::string crs_of(const CatalogueTile& t) {
  return t.header.crs.describe() + " (" + t.header.crs.units.short_text() + ")";
}

}  // namespace

bool expand_tile_arguments(const std::vector<std::string>& args, std::vector<std::string>* paths,
                           std::string* error) {
  paths->clear();
  for (const std::string& a : args) {
    std::error_code ec;
    if (fs::is_directory(a, ec)) {
      const size_t before = paths->size();
      for (const fs::directory_entry& e : fs::directory_iterator(a, ec))
        if (e.is_regular_file() && cloud_extension(e.path())) paths->push_back(e.path().string());
      if (paths->size() == before) {
        *error = a + ": no point-cloud file (.las .laz .ply .txt .xyz .csv) in this folder";
        return false;
      }
    } else if (fs::exists(a, ec)) {
      paths->push_back(a);
    } else {
      *error = a + ": no such file or folder";
      return false;
    }
  }
  std::sort(paths->begin(), paths->end());
  paths->erase(std::unique(paths->begin(), paths->end()), paths->end());
  return true;
}

Catalogue read_catalogue(const std::vector<std::string>& sorted_paths) {
  Catalogue c;
  for (const std::string& path : sorted_paths) {
    CatalogueTile t;
    t.path = path;
    t.name = host::cloud_name(path);
    try {
      t.header = host::read_cloud_header(path);
    } catch (const std::exception& e) {
      t.error = e.what();
    }
    c.tiles.push_back(std::move(t));
  }
  return c;
}

bool check_catalogue(Catalogue& catalogue, const host::WorkCrs& work, std::string* error) {
  catalogue.crs = work.crs;
  catalogue.crs_named = work.named;
  catalogue.notes.clear();
  std::map<std::string, std::string> names;
  const CatalogueTile* first_known = nullptr;
  for (const CatalogueTile& t : catalogue.tiles) {
    if (!names.emplace(t.name, t.path).second) {
      *error = "two tiles named " + t.name + ": " + names[t.name] + " and " + t.path +
               " (each tile's outputs are named after its file; rename one)";
      return false;
    }
    if (!t.error.empty() || !t.header.crs.known()) continue;
    if (!work.named && t.header.crs.units.geographic) {
      *error = t.path + " is in " + t.header.crs.describe() +
               ", a geographic CRS: " + t.header.crs.units.describe();
      return false;
    }
    if (first_known == nullptr) {
      first_known = &t;
    } else if (!work.named && !host::same_crs(first_known->header.crs, t.header.crs)) {
      *error = "the tiles do not share a CRS: " + first_known->path + " is " + crs_of(*first_known) + ", " +
               t.path + " is " + crs_of(t) +
               " (reproject them to one CRS, or name one to work in: --work-crs EPSG:n)";
      return false;
    } else if (!work.named && first_known->header.crs.describe() != t.header.crs.describe()) {
      catalogue.notes.push_back(t.name + " declares " + t.header.crs.describe() + ", the same CRS as " +
                                first_known->header.crs.describe());
    }
  }
  if (!work.named && first_known != nullptr) catalogue.crs = first_known->header.crs;
  for (CatalogueTile& t : catalogue.tiles) {
    if (!t.error.empty()) continue;
    if (!t.header.crs.known() && catalogue.crs.known())
      catalogue.notes.push_back(t.name + " declares no CRS: assumed to be in " + catalogue.crs.describe());
    else if (work.named && t.header.crs.known() && !host::same_crs(t.header.crs, work.crs))
      catalogue.notes.push_back(t.name + " reprojected from " + t.header.crs.describe() + " to " +
                                work.crs.describe());
    try {
      metric_bounds(t, catalogue.work());
    } catch (const std::exception& e) {
      t.error = e.what();
    }
  }
  if (!catalogue.crs.known() && !catalogue.tiles.empty())
    catalogue.notes.push_back("no tile declares a CRS: outputs are in the tiles' own coordinates");
  return true;
}

}  // namespace spinhash::survey
