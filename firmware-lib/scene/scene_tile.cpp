#include "spinhash/scene_tile.hpp"

#include <cmath>

#include "spinhash/limits.hpp"

namespace spinhash {

uint32_t scene_grid_cells(double w, double h, float cell) noexcept {
  const double c = static_cast<double>(cell);
  const double cells = (std::ceil(w / c) + 2.0) * (std::ceil(h / c) + 2.0);
  return cells < static_cast<double>(kMaxSceneGridCells) ? static_cast<uint32_t>(cells) : kMaxSceneGridCells;
}

void fit_tile_grids(SceneConfig* scene) noexcept {
  const double core = static_cast<double>(scene->window_core),
               margin = static_cast<double>(scene->window_margin);
  const double band = static_cast<double>(scene->band_columns) * core;
  const double gathered = core + 2.0 * static_cast<double>(scene->object_margin);
  const uint32_t terrain = scene_grid_cells(band + 2.0 * margin, core + 2.0 * margin, scene->terrain_cell);
  const uint32_t segment = scene_grid_cells(gathered, gathered, scene->segment_cell);
  scene->max_terrain_cells = scene->max_terrain_cells > terrain ? scene->max_terrain_cells : terrain;
  scene->max_segment_cells = scene->max_segment_cells > segment ? scene->max_segment_cells : segment;
}

StreamConfig tile_stream_config(const SceneConfig& scene, uint32_t max_buffered_points) noexcept {
  StreamConfig c;
  c.scene = scene;
  const double core = static_cast<double>(scene.window_core),
               margin = static_cast<double>(scene.window_margin);
  const double object_margin = static_cast<double>(scene.object_margin);
  const double band = static_cast<double>(scene.band_columns) * core;
  c.origin_given = true;  // each band's, by SceneStream::reset
  c.heading_deg = 0.0f;   // rows along x
  c.own_min = 0.0f;
  c.own_max = static_cast<float>(band);
  c.swath_min = -static_cast<float>(margin);
  c.swath_max = static_cast<float>(band + margin);
  c.max_lag = scene.row_depth;  // a row's points come in any order
  c.max_jump = kMaxStreamExtent;
  c.max_z_offset = kMaxStreamExtent;
  const double seen_across = band + 2.0 * margin, gathered = core + 2.0 * object_margin;
  // The buffer holds a row's gathered points, its terrain lookahead and a
  // row's lag, across the band and its margins (points beyond the gathered
  // band are forgotten once their terrain cells are summed).
  double buffered = static_cast<double>(max_buffered_points);
  if (max_buffered_points == 0) {
    const double area = (core + object_margin + margin + static_cast<double>(scene.row_depth)) * seen_across;
    buffered = std::ceil(static_cast<double>(scene.max_tile_points) * area / (gathered * gathered));
  }
  c.max_buffered_points = buffered < static_cast<double>(kMaxStreamBufferedPoints)
                              ? (buffered > 1.0 ? static_cast<uint32_t>(buffered) : 1u)
                              : kMaxStreamBufferedPoints;
  return c;
}

TilePlan plan_tile(const SceneConfig& scene, const double* lo, const double* hi) noexcept {
  TilePlan p;
  const double core = static_cast<double>(scene.window_core);
  p.origin[0] = std::floor(lo[0] / core) * core;
  p.origin[1] = std::floor(lo[1] / core) * core;
  p.origin[2] = lo[2];
  p.band_width = static_cast<double>(scene.band_columns) * core;
  p.row_depth = static_cast<double>(scene.row_depth);
  p.object_margin = static_cast<double>(scene.object_margin);
  const double bands = std::floor((hi[1] - p.origin[1]) / p.band_width) + 1.0;
  p.bands = bands < 1.0 ? 1u : (bands < 4.0e9 ? static_cast<uint32_t>(bands) : 0xFFFFFFFFu);
  return p;
}

void tile_band_origin(const TilePlan& plan, uint32_t b, double* origin) noexcept {
  origin[0] = plan.origin[0];
  origin[1] = plan.origin[1] + static_cast<double>(b) * plan.band_width;
  origin[2] = plan.origin[2];
}

uint32_t tile_band_gathering(const TilePlan& plan, double y) noexcept {
  // Band b gathers [b w - m, (b + 1) w + m) from the origin.
  const double b =
      std::floor((y - plan.origin[1] - plan.object_margin - plan.band_width) / plan.band_width) + 1.0;
  if (!(b < static_cast<double>(plan.bands))) return plan.bands;  // beyond the last, or NaN
  return b < 0.0 ? 0u : static_cast<uint32_t>(b);
}

int64_t tile_row(const TilePlan& plan, double x) noexcept {
  return static_cast<int64_t>(std::floor(x / plan.row_depth));
}

}  // namespace spinhash
