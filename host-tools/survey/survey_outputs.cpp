#include "survey/survey_outputs.hpp"

#include <map>

#include "blob/file_io.hpp"
#include "pipeline/json_line.hpp"
#include "pipeline/version.hpp"
#include "render/survey_picture.hpp"
#include "survey/gpkg_writer.hpp"

namespace spinhash::survey {
namespace {

using pipeline::json_number;
using pipeline::json_string;

bool write_text(const std::string& path, const std::string& text, std::string* error) {
  return host::write_file_atomically(path, text.data(), text.size(), error);
}

std::string geometry_note(const Catalogue& c) {
  return c.crs.known() ? "WGS 84 longitude/latitude (RFC 7946), transformed from " + c.crs.describe()
                       : "the tiles' own coordinates: no tile declares a CRS";
}

std::string geojson(const Catalogue& c, const std::vector<TileResult>& done) {
  std::string s =
      "{\"type\":\"FeatureCollection\",\"name\":\"spinhash detections\",\"spinhash\":{\"source_crs\":" +
      json_string(c.crs.describe()) + ",\"geometry\":" + json_string(geometry_note(c)) +
      ",\"version\":" + json_string(pipeline::version()) + "},\"features\":[";
  bool first = true;
  for (const TileResult& r : done)
    for (const std::string& f : r.features) {
      s += (first ? "\n" : ",\n") + f;
      first = false;
    }
  return s + "\n]}\n";
}

// The units of the outputs' coordinates (the survey CRS's; metres when unknown).
std::string units_json(const host::AxisUnits& u) {
  if (u.geographic)
    return "{\"horizontal\":\"degree\",\"horizontal_m\":null,\"vertical\":null,\"vertical_m\":null}";
  return "{\"horizontal\":" + json_string(u.horizontal_name) +
         ",\"horizontal_m\":" + json_number(u.horizontal, 15) +
         ",\"vertical\":" + json_string(u.vertical_name) + ",\"vertical_m\":" + json_number(u.vertical, 15) +
         "}";
}

std::string models_json(const std::map<std::string, ModelCount>& models) {
  std::string s = "{";
  for (const auto& kv : models)
    s += (s.size() > 1 ? "," : "") + json_string(kv.first) +
         ":{\"candidates\":" + std::to_string(kv.second.candidates) +
         ",\"confident\":" + std::to_string(kv.second.confident) + "}";
  return s + "}";
}

std::string kinds_json(const std::map<std::string, uint32_t>& kinds) {
  std::string s = "{";
  for (const auto& kv : kinds)
    s += (s.size() > 1 ? "," : "") + json_string(kv.first) + ":" + std::to_string(kv.second);
  return s + "}";
}

std::string tile_json(const TileResult& r) {
  return "{\"tile\":" + json_string(r.name) + ",\"path\":" + json_string(r.path) +
         ",\"status\":" + json_string(r.status) + ",\"points\":" + std::to_string(r.points_tile) +
         ",\"buffer_points\":" + std::to_string(r.points_buffer) +
         ",\"noise_points\":" + std::to_string(r.points_noise) +
         ",\"objects\":" + std::to_string(r.lines.size()) +
         ",\"vehicle_candidates\":" + std::to_string(r.features.size()) +
         ",\"objects_owned_by_neighbours\":" + std::to_string(r.objects_not_owned) +
         ",\"objects_in_holes\":" + std::to_string(r.objects_in_holes) +
         ",\"read_ms\":" + json_number(r.read_ms, 6) + ",\"stream_ms\":" + json_number(r.stream_ms, 6) +
         ",\"total_ms\":" + json_number(r.total_ms, 6) + ",\"kinds\":" + kinds_json(r.kinds) +
         ",\"models\":" + models_json(r.models) + "}";
}

std::string survey_json(const Catalogue& c, const std::vector<TileResult>& done, const SurveyReport& rep) {
  std::map<std::string, ModelCount> models;
  std::map<std::string, uint32_t> kinds;
  uint64_t points = 0, buffer_points = 0, noise_points = 0;
  double read_ms = 0, stream_ms = 0;
  std::string tiles, refused, notes;
  for (const TileResult& r : done) {
    for (const auto& kv : r.models)
      models[kv.first].candidates += kv.second.candidates, models[kv.first].confident += kv.second.confident;
    for (const auto& kv : r.kinds) kinds[kv.first] += kv.second;
    points += r.points_tile, buffer_points += r.points_buffer, noise_points += r.points_noise;
    read_ms += r.read_ms, stream_ms += r.stream_ms;
    tiles += (tiles.empty() ? "\n  " : ",\n  ") + tile_json(r);
  }
  for (const Refusal& f : rep.refused)
    refused += (refused.empty() ? "" : ",") + std::string("{\"tile\":") + json_string(f.tile) +
               ",\"path\":" + json_string(f.path) + ",\"reason\":" + json_string(f.reason) + "}";
  for (const std::string& n : c.notes) notes += (notes.empty() ? "" : ",") + json_string(n);
  std::string dropped;
  for (int k : rep.dropped_classes) dropped += (dropped.empty() ? "" : ",") + std::to_string(k);
  return "{\"version\":" + json_string(pipeline::version()) + ",\"database\":" + json_string(rep.database) +
         ",\"buffer_m\":" + json_number(rep.buffer) + ",\"jobs\":" + std::to_string(rep.jobs) +
         ",\"crs\":" + json_string(c.crs.describe()) + ",\"crs_units\":" + units_json(c.crs.units) +
         ",\"geometry\":" + json_string(geometry_note(c)) + ",\"notes\":[" + notes +
         "],\"tiles_total\":" + std::to_string(rep.tiles_total) +
         ",\"tiles_done\":" + std::to_string(done.size()) +
         ",\"tiles_resumed\":" + std::to_string(rep.tiles_resumed) +
         ",\"tiles_refused\":" + std::to_string(rep.refused.size()) +
         ",\"points\":" + std::to_string(points) + ",\"buffer_points\":" + std::to_string(buffer_points) +
         ",\"noise_points\":" + std::to_string(noise_points) + ",\"dropped_classes\":[" + dropped +
         "],\"segment_cell_m\":" + json_number(rep.segment_cell) +
         ",\"wall_s\":" + json_number(rep.wall_s, 6) + ",\"stage_ms\":{\"read\":" + json_number(read_ms, 9) +
         ",\"stream\":" + json_number(stream_ms, 9) + "},\"kinds\":" + kinds_json(kinds) +
         ",\"models\":" + models_json(models) + ",\"refused\":[" + refused + "],\"tiles\":[" + tiles +
         "\n]}\n";
}

bool write_overview(const std::string& path, const Catalogue& c, const std::vector<TileResult>& done,
                    std::string* error) {
  std::vector<host::SurveyPictureTile> tiles;
  for (const CatalogueTile& t : c.tiles)
    if (t.error.empty())
      tiles.push_back({{t.header.min[0], t.header.min[1]}, {t.header.max[0], t.header.max[1]}, t.name});
  std::vector<host::PictureBox> boxes;
  uint32_t vehicles = 0, confident = 0;
  for (const TileResult& r : done)
    for (const host::PictureBox& b : r.boxes) {
      boxes.push_back(b);
      vehicles += b.style != host::BoxStyle::kNotVehicle, confident += b.style == host::BoxStyle::kConfident;
    }
  const std::string title = std::to_string(done.size()) + " of " + std::to_string(c.tiles.size()) +
                            " tiles: " + std::to_string(vehicles) + " vehicles, " +
                            std::to_string(confident) + " confident";
  return tiles.empty() || host::write_survey_picture(path, tiles, boxes, title, error);
}

}  // namespace

std::string without_path(const std::string& reason, const std::string& path) {
  const std::string prefix = path + ": ";
  return reason.compare(0, prefix.size(), prefix) == 0 ? reason.substr(prefix.size()) : reason;
}

Refusal refusal(const std::string& tile, const std::string& path, const std::string& reason) {
  return {tile, path, without_path(reason, path)};
}

bool write_survey_outputs(const std::string& dir, const Catalogue& catalogue,
                          const std::vector<TileResult>& done, const SurveyReport& report,
                          std::string* error) {
  std::string lines;
  for (const TileResult& r : done)
    for (const std::string& l : r.lines) lines += l + "\n";
  std::vector<std::string> features;
  std::vector<Column> columns;
  for (const TileResult& r : done) {
    features.insert(features.end(), r.features.begin(), r.features.end());
    if (columns.empty()) columns = r.columns;
  }
  return write_text(dir + "/detections.jsonl", lines, error) &&
         write_text(dir + "/detections.geojson", geojson(catalogue, done), error) &&
         write_geopackage(features, columns, dir + "/detections.gpkg", catalogue.crs.proj_definition(),
                          error) &&
         write_overview(dir + "/overview.png", catalogue, done, error) &&
         write_text(dir + "/survey.json", survey_json(catalogue, done, report), error);
}

}  // namespace spinhash::survey
