// The survey's outputs in DIR, assembled from the tiles' stored results in
// path order (so identical for any number of jobs or workers, and a re-run
// never duplicates): detections.jsonl, detections.geojson,
// detections.gpkg and survey.json.
#pragma once
#include <string>
#include <vector>

#include "survey/catalogue.hpp"
#include "survey/tile_result.hpp"

namespace spinhash::survey {

struct Refusal {
  std::string tile, path, reason;
};

// A refusal whose reason does not repeat the path (readers' messages begin
// with it): "LAZ: chunk 2: ...", not "/x/a.laz: LAZ: chunk 2: ...".
Refusal refusal(const std::string& tile, const std::string& path, const std::string& reason);
// The reason without a leading "path: ".
std::string without_path(const std::string& reason, const std::string& path);

struct SurveyReport {
  std::string database;
  double buffer = 0;
  unsigned jobs = 0;
  std::vector<int> dropped_classes;  // LAS classes the readers left out (cloud/point_filter.hpp)
  float segment_cell = 0.0f;         // m: every tile's segmentation cell (pipeline/segment_cell.hpp)
  uint32_t tiles_total = 0, tiles_resumed = 0;
  double wall_s = 0;
  std::vector<Refusal> refused;  // headers not read, tiles or neighbours unreadable
};

// Writes every output; false with *error when one cannot be written.
bool write_survey_outputs(const std::string& dir, const Catalogue& catalogue,
                          const std::vector<TileResult>& done, const SurveyReport& report,
                          std::string* error);

}  // namespace spinhash::survey
