// The plan of a survey: one task per readable tile. A task travels as text
// (to a thread, or to a Dask worker: paths travel, points do not) and holds
// all a worker needs: the tile, its core, the rectangle it sees (core plus
// the buffer) and the neighbours whose points fall in it.
//
// Ownership (the core's owner_of, spinhash/scene_ownership.hpp; lidR's
// catalogue rule, docs/survey.md): an object belongs to the first tile, in
// path order, whose half-open core [min, max) holds its centre. Cores are
// the headers' bounds, which are the points' extents, so adjacent tiles
// leave thin gaps between them: a centre in no core goes to the nearest
// core within kGapTolerance. Every tile within kGapTolerance of a centre it
// owns is its neighbour, so each tile decides alone and all agree
// (survey/tile_run.hpp: owner_areas).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "cloud/metric_source.hpp"
#include "survey/catalogue.hpp"

namespace spinhash::survey {

// Half the longest vehicle (max_length 13 m / 2 = 6.5 m) plus the terrain
// filter's reach (openings of up to 16 cells of 0.5 m, eroded and dilated:
// 31 m), rounded up: 37.5 -> 40 m, the stream's window margin. A vehicle
// whose centre lies in a tile's core is then seen whole, on the same terrain.
constexpr double kDefaultBuffer = 40.0;
constexpr double kMinBuffer = 0.0, kMaxBuffer = 1000.0;  // m; more would read whole neighbours many times
// Gaps between tiles' bounds (points' extents, not the tiling's cut lines)
// up to twice this belong to the nearest tile; wider gaps are holes.
constexpr double kGapTolerance = 1.0;  // m

struct Rect {
  double min[2] = {0, 0}, max[2] = {0, 0};
  bool holds(double x, double y) const { return x >= min[0] && x < max[0] && y >= min[1] && y < max[1]; }
  Rect grown(double d) const;
  bool intersects(const Rect& o) const;
};

struct TaskTile {
  std::string path, name;
  Rect core;
};

// Rectangles are in metres of the survey's CRS (cloud/metric_source.hpp),
// as the tiles' points are read.
struct SurveyTask {
  uint32_t index = 0;  // in the catalogue (sorted paths)
  TaskTile tile;
  std::vector<TaskTile> neighbours;  // path order; bounds within the seen rectangle
  Rect seen;                         // core grown by the buffer
  std::string crs;                   // the survey CRS's PROJ definition ("": unknown)
  bool crs_named = false;            // the user named it: tiles in other CRSs are reprojected into it
  std::string crs_name;              // "EPSG:25832", "unknown"
  host::AxisUnits units;      // of the survey CRS: outputs go back to them (name and notes not carried)
  host::PointFilter filter;   // the points every tile's reader leaves out
  float segment_cell = 0.0f;  // m: the survey's segmentation cell (0: the scene setting's, grown per tile)
  std::string key;            // the inputs the result depends on (resume reuses equal keys only)

  // The survey's CRS as the reading door takes it (resolved through PROJ).
  host::WorkCrs work() const;
};

// One task per tile whose header was read. settings: the database's digest
// and the recognition settings, part of every key.
std::vector<SurveyTask> plan_survey(const Catalogue& catalogue, double buffer, const std::string& settings);

std::string task_text(const SurveyTask& task);
bool parse_task_text(const std::string& text, SurveyTask* task, std::string* error);

// One line of text, whatever it holds: backslash, newline and tab escaped.
std::string escape_line(const std::string& s);
std::string unescape_line(const std::string& s);

}  // namespace spinhash::survey
