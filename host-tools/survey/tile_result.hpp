// What one tile of a survey gives: its detections, already as the output
// lines (JSON lines, GeoJSON features), and its counts and times. Stored as
// one text file per tile (written atomically: the tile is done when it
// exists), read back to assemble the survey's outputs in path order.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "render/tile_picture.hpp"

namespace spinhash::survey {

struct ModelCount {
  uint32_t candidates = 0;  // vehicle candidates ranked first as this model
  uint32_t confident = 0;
};

// A column of the detections' GeoPackage: a member of the JSON lines and
// the type its values take (survey/gpkg_writer.hpp).
enum class ColumnType : char { kString = 's', kJson = 'j', kInteger = 'i', kReal = 'r', kBoolean = 'b' };
struct Column {
  std::string name;
  ColumnType type = ColumnType::kString;
};

struct TileResult {
  uint32_t index = 0;
  std::string name, path, key;
  std::string status = "ok";  // the stream's status word
  uint64_t points_tile = 0, points_buffer = 0;
  uint64_t points_noise = 0;       // the tile's points its file marks as noise or withheld: left out
  uint64_t objects_not_owned = 0;  // centres a neighbour owns
  uint64_t objects_in_holes = 0;   // centres farther than kGapTolerance from every tile
  double read_ms = 0, stream_ms = 0, total_ms = 0;
  std::map<std::string, uint32_t> kinds;
  std::map<std::string, ModelCount> models;
  std::vector<std::string> lines;       // detections.jsonl, one per object
  std::vector<std::string> features;    // detections.geojson, one per vehicle candidate
  std::vector<host::PictureBox> boxes;  // overview.png, one per object
  std::vector<Column> columns;          // the members of a detection, typed (the same for every tile)
};

std::string result_text(const TileResult& r);
bool parse_result_text(const std::string& text, TileResult* r, std::string* error);

}  // namespace spinhash::survey
