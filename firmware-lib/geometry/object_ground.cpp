#include "geometry/object_ground.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>

#include "util/far.hpp"
#include "util/heap_sort.hpp"

namespace spinhash {
namespace {

constexpr float kEmptyCell = kFar;      // lowest point of a cell without points
constexpr uint32_t kMinPlaneCells = 3;  // a plane through fewer is not determined
// CellStats::spread of a cell without min_roughness_points ground points:
// none (kUnmeasured), or a few, all within roughness_band of its low lowest
// point (kSparseFlat: ground a sparse scan samples thinly; at 10-20 points
// per m^2 the 1 m cells the footprint's edge cuts hold 1-4 points).
constexpr float kUnmeasured = -1.0f;
constexpr float kSparseFlat = -2.0f;

struct Grid {
  float x0 = 0.0f, y0 = 0.0f, cell = 0.0f;
  uint32_t cell_of(const float* p) const { return index_of(p, 1u); }
  // The index of p's square in the grid with each cell split in split x split.
  uint32_t index_of(const float* p, uint32_t split) const {
    const float size = cell / static_cast<float>(split);
    const uint32_t side = kTerrainGridSide * split;
    int32_t i = static_cast<int32_t>((p[0] - x0) / size), j = static_cast<int32_t>((p[1] - y0) / size);
    const int32_t last = static_cast<int32_t>(side) - 1;
    i = i < 0 ? 0 : (i > last ? last : i);
    j = j < 0 ? 0 : (j > last ? last : j);
    return static_cast<uint32_t>(j) * side + static_cast<uint32_t>(i);
  }
  float centre_x(uint32_t c) const { return x0 + (static_cast<float>(c % kTerrainGridSide) + 0.5f) * cell; }
  float centre_y(uint32_t c) const { return y0 + (static_cast<float>(c / kTerrainGridSide) + 0.5f) * cell; }
};

struct Plane {
  float a = 0.0f, b = 0.0f, c = 0.0f;  // z = a x + b y + c
  float at(float x, float y) const { return a * x + b * y + c; }
};

Grid footprint(const float* xyz, uint32_t n, float min_cell) {
  float lo[2] = {xyz[0], xyz[1]}, hi[2] = {xyz[0], xyz[1]};
  for (uint32_t i = 1; i < n; ++i)
    for (uint32_t a = 0; a < 2; ++a) {
      const float v = xyz[3u * i + a];
      lo[a] = v < lo[a] ? v : lo[a];
      hi[a] = v > hi[a] ? v : hi[a];
    }
  Grid g;
  g.x0 = lo[0];
  g.y0 = lo[1];
  const float extent = hi[0] - lo[0] > hi[1] - lo[1] ? hi[0] - lo[0] : hi[1] - lo[1];
  const float cell = extent / static_cast<float>(kTerrainGridSide);
  g.cell = cell > min_cell ? cell : min_cell;
  return g;
}

uint32_t occupied_cells(const float* lowest) {
  uint32_t occupied = 0;
  for (uint32_t c = 0; c < kTerrainCells; ++c) occupied += lowest[c] != kEmptyCell ? 1u : 0u;
  return occupied;
}

void lowest_points(const float* xyz, uint32_t n, const Grid& g, float* lowest) {
  for (uint32_t c = 0; c < kTerrainCells; ++c) lowest[c] = kEmptyCell;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t c = g.cell_of(xyz + 3u * i);
    lowest[c] = xyz[3u * i + 2u] < lowest[c] ? xyz[3u * i + 2u] : lowest[c];
  }
}

// Least-squares plane through the lowest points of the cells that rise at
// most max_rise above `previous` (all occupied cells without one).
bool fit_plane(const Grid& g, const float* lowest, const Plane* previous, float max_rise, Plane* out) {
  Eigen::Matrix3f ata = Eigen::Matrix3f::Zero();
  Eigen::Vector3f atz = Eigen::Vector3f::Zero();
  uint32_t used = 0;
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    if (lowest[c] == kEmptyCell) continue;
    const float x = g.centre_x(c), y = g.centre_y(c);
    if (previous != nullptr && lowest[c] - previous->at(x, y) > max_rise) continue;
    const Eigen::Vector3f row(x, y, 1.0f);
    ata.noalias() += row * row.transpose();
    atz += row * lowest[c];
    ++used;
  }
  if (used < kMinPlaneCells) return false;
  const Eigen::LDLT<Eigen::Matrix3f> ldlt(ata);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return false;
  const Eigen::Vector3f abc = ldlt.solve(atz);
  if (!abc.allFinite()) return false;
  *out = Plane{abc[0], abc[1], abc[2]};
  return true;
}

bool fit_terrain_plane(const Grid& g, const float* lowest, const GroundParams& p, Plane* plane) {
  if (!fit_plane(g, lowest, nullptr, 0.0f, plane)) return false;
  for (uint32_t round = 1; round < p.fit_rounds; ++round) {
    const Plane previous = *plane;
    const float rise = round <= p.coarse_rounds ? p.object_cell_rise : p.ground_cell_rise;
    if (!fit_plane(g, lowest, &previous, rise, plane)) return false;
  }
  return std::sqrt(plane->a * plane->a + plane->b * plane->b) <= p.max_ground_slope;
}

// Per cell, over its ground points (those within roughness_band of the
// lowest point of a cell that rises at most ground_cell_rise above the
// plane): their mean height above the plane and their spread.
struct CellStats {
  float* mean;    // level: becomes the cell's ground level
  float* spread;  // sigma of the ground points; < 0: no usable ground
  float* count;   // points; then scratch for the median
};

void accumulate(const float* xyz, uint32_t n, const Grid& g, const Plane& plane, const float* lowest,
                const GroundParams& p, const CellStats& cs) {
  for (uint32_t c = 0; c < kTerrainCells; ++c) cs.mean[c] = cs.spread[c] = cs.count[c] = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    const float* x = xyz + 3u * i;
    const uint32_t c = g.cell_of(x);
    if (lowest[c] - plane.at(g.centre_x(c), g.centre_y(c)) > p.ground_cell_rise ||
        x[2] > lowest[c] + p.roughness_band)
      continue;
    const float d = x[2] - plane.at(x[0], x[1]);
    cs.mean[c] += d;
    cs.spread[c] += d * d;
    cs.count[c] += 1.0f;
  }
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    if (cs.count[c] < static_cast<float>(p.min_roughness_points)) {
      cs.spread[c] = cs.count[c] > 0.0f ? kSparseFlat : kUnmeasured;
      continue;
    }
    cs.mean[c] /= cs.count[c];
    const float var = cs.spread[c] / cs.count[c] - cs.mean[c] * cs.mean[c];
    cs.spread[c] = std::sqrt(var > 0.0f ? var : 0.0f);
  }
}

// Sparse-flat cells with a point above the roughness band hold an object.
void unflatten_occupied(const float* xyz, uint32_t n, const Grid& g, const float* lowest,
                        float roughness_band, const CellStats& cs) {
  for (uint32_t i = 0; i < n; ++i) {
    const float* x = xyz + 3u * i;
    const uint32_t c = g.cell_of(x);
    if (cs.spread[c] == kSparseFlat && x[2] > lowest[c] + roughness_band) cs.spread[c] = kUnmeasured;
  }
}

// The ground's roughness: the median spread of the ground cells (objects
// standing in a minority of them widen theirs, not the median).
float median_spread(const CellStats& cs, uint32_t* ground_cells) {
  uint32_t k = 0;
  for (uint32_t c = 0; c < kTerrainCells; ++c)
    if (cs.spread[c] >= 0.0f) cs.count[k++] = cs.spread[c];
  *ground_cells = k;
  if (k == 0) return 0.0f;
  heap_sort(cs.count, k, [](float a, float b) { return a < b; });
  return cs.count[k / 2u];
}

// Clean ground cells (spread at most clean_spread_factor x the median)
// flagged in count.
void mark_clean(const CellStats& cs, float sigma, const GroundParams& p) {
  const float clean = p.clean_spread_factor * sigma + p.spread_slack;
  for (uint32_t c = 0; c < kTerrainCells; ++c)
    cs.count[c] = cs.spread[c] >= 0.0f && cs.spread[c] <= clean ? 1.0f : 0.0f;
}

bool occupied_at(const float* lowest, int32_t i, int32_t j) {
  const int32_t side = static_cast<int32_t>(kTerrainGridSide);
  return i >= 0 && j >= 0 && i < side && j < side &&
         lowest[static_cast<uint32_t>(j * side + i)] != kEmptyCell;
}

// Share of the footprint's border cells (occupied, with an empty 4-neighbour)
// that are clean ground: terrain reaches beyond the objects on it, while a
// bare object's outline is its sides. With `sparse` cells (grown for a
// sparse scan) a sparse-flat border cell counts as clean: a cell the
// footprint's edge cuts holds too few points for a spread.
float clean_border_share(const float* lowest, const CellStats& cs, bool sparse) {
  uint32_t border = 0, clean = 0;
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    if (lowest[c] == kEmptyCell) continue;
    const int32_t i = static_cast<int32_t>(c % kTerrainGridSide),
                  j = static_cast<int32_t>(c / kTerrainGridSide);
    if (occupied_at(lowest, i - 1, j) && occupied_at(lowest, i + 1, j) && occupied_at(lowest, i, j - 1) &&
        occupied_at(lowest, i, j + 1))
      continue;
    ++border;
    clean += cs.count[c] > 0.0f || (sparse && cs.spread[c] == kSparseFlat) ? 1u : 0u;
  }
  return border > 0 ? static_cast<float>(clean) / static_cast<float>(border) : 0.0f;
}

uint32_t clean_cells(const CellStats& cs) {
  uint32_t k = 0;
  for (uint32_t c = 0; c < kTerrainCells; ++c) k += cs.count[c] > 0.0f ? 1u : 0u;
  return k;
}

// What the clean ground cells prove: terrain (enough of them), terrain if
// they ring the footprint and a body stands on them (a sparse scan with
// min_ringed_ground_cells or more), or nothing.
enum class CleanGround { kTerrain, kTerrainIfRinged, kNone };

CleanGround clean_ground(const CellStats& cs, const Grid& g, bool sparse, const GroundParams& p) {
  const uint32_t clean = clean_cells(cs);
  if (!sparse)
    return static_cast<float>(clean) * g.cell * g.cell < p.min_dense_ground_area ? CleanGround::kNone
                                                                                 : CleanGround::kTerrain;
  if (clean >= p.min_sparse_ground_cells) return CleanGround::kTerrain;
  return clean >= p.min_ringed_ground_cells ? CleanGround::kTerrainIfRinged : CleanGround::kNone;
}

// Clean ground cells keep their mean as level; the others take their clean
// neighbours' mean, or 0.
void fill_levels(const CellStats& cs) {
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    if (cs.count[c] > 0.0f) continue;
    const int32_t ci = static_cast<int32_t>(c % kTerrainGridSide),
                  cj = static_cast<int32_t>(c / kTerrainGridSide);
    float s = 0.0f, k = 0.0f;
    for (int32_t dj = -1; dj <= 1; ++dj)
      for (int32_t di = -1; di <= 1; ++di) {
        const int32_t i = ci + di, j = cj + dj, side = static_cast<int32_t>(kTerrainGridSide);
        if (i < 0 || j < 0 || i >= side || j >= side) continue;
        const uint32_t nb = static_cast<uint32_t>(j * side + i);
        if (cs.count[nb] > 0.0f) s += cs.mean[nb], k += 1.0f;
      }
    cs.mean[c] = k > 0.0f ? s / k : 0.0f;
    cs.count[c] = -1.0f;  // filled: not a source for later cells (the fill stays one cell deep)
  }
}

// The terrain's level under a point: the plane plus its cell's level.
struct Level {
  const Grid& g;
  const Plane& plane;
  const float* mean;
  float height(const float* p) const { return p[2] - plane.at(p[0], p[1]) - mean[g.cell_of(p)]; }
};

// How many points lie within the band (`near`) and deeper than `below`
// under the terrain (`under`), and the highest point's height.
struct BandCounts {
  uint32_t near = 0, under = 0;
  float highest = 0.0f;
};

// Per column, the highest point above the terrain, and the band counts, in
// one pass (one height per point).
BandCounts column_tops(const float* xyz, uint32_t n, const Level& level, float drop, float below,
                       float* tops) {
  for (uint32_t c = 0; c < kColumnCells; ++c) tops[c] = -kEmptyCell;
  BandCounts counts;
  for (uint32_t i = 0; i < n; ++i) {
    const float* p = xyz + 3u * i;
    const uint32_t c = level.g.index_of(p, kColumnSplit);
    const float h = level.height(p);
    tops[c] = h > tops[c] ? h : tops[c];
    counts.highest = h > counts.highest ? h : counts.highest;
    counts.near += h <= drop ? 1u : 0u;
    counts.under += h < below ? 1u : 0u;
  }
  return counts;
}

// Compacts xyz to the points above the band (`drop` m over the terrain) and
// the band's top in a column that holds a body; returns how many stay, and
// the two highest of them above their terrain in top.
uint32_t keep_above_band(float* xyz, uint32_t n, const Level& level, float drop, const GroundParams& gp,
                         const float* tops, float top[2]) {
  const float body = drop + gp.body_above;            // a column rising this high holds a body
  const float body_floor = gp.band_kept_from * drop;  // band points below it are ground even there
  uint32_t kept = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const float* p = xyz + 3u * i;
    const float h = level.height(p);
    if (h <= drop && (h <= body_floor || tops[level.g.index_of(p, kColumnSplit)] < body)) continue;
    if (h > top[1]) top[1] = h > top[0] ? top[0] : h;
    if (h > top[0]) top[0] = h;
    for (uint32_t a = 0; a < 3u; ++a) xyz[3u * kept + a] = p[a];
    ++kept;
  }
  return kept;
}

}  // namespace

uint32_t remove_object_ground(float* xyz, uint32_t n, const GroundParams& p, float* scratch,
                              TerrainUnder* terrain) {
  if (terrain != nullptr) *terrain = TerrainUnder{};
  if (n == 0 || !p.enabled || !(p.ground_clearance > 0.0f)) return 0;
  float* lowest = scratch;
  const CellStats cs{scratch + kTerrainCells, scratch + 2u * kTerrainCells, scratch + 3u * kTerrainCells};
  Grid g = footprint(xyz, n, p.min_ground_cell);
  lowest_points(xyz, n, g, lowest);
  uint32_t occupied = occupied_cells(lowest);
  // A sparse scan: cells scaled so that they hold min_points_per_cell points
  // on average (the occupied area grows with the cell too, so this is a lower
  // bound on the scale), once, up to max_ground_cell. The grid keeps its
  // corner; the larger cell still covers the footprint.
  const float per_cell = static_cast<float>(n) / static_cast<float>(occupied > 0u ? occupied : 1u);
  if (per_cell < p.min_points_per_cell && g.cell < p.max_ground_cell) {
    const float wanted = g.cell * std::sqrt(p.min_points_per_cell / per_cell);
    g.cell = wanted < p.max_ground_cell ? wanted : p.max_ground_cell;
    lowest_points(xyz, n, g, lowest);
    occupied = occupied_cells(lowest);
  }
  Plane plane;
  if (!fit_terrain_plane(g, lowest, p, &plane)) return 0;
  uint32_t ground_cells = 0;
  accumulate(xyz, n, g, plane, lowest, p, cs);
  const float sigma = median_spread(cs, &ground_cells);
  if (static_cast<float>(ground_cells) < p.min_ground_cell_share * static_cast<float>(occupied) ||
      sigma > p.max_ground_roughness)
    return 0;
  mark_clean(cs, sigma, p);
  const bool sparse = g.cell > p.min_ground_cell;  // cells grown for a sparse scan
  const CleanGround proof = clean_ground(cs, g, sparse, p);
  if (proof == CleanGround::kNone) return 0;
  const bool ringed = proof == CleanGround::kTerrainIfRinged;
  unflatten_occupied(xyz, n, g, lowest, p.roughness_band, cs);
  const float border = clean_border_share(lowest, cs, sparse);
  if (border < (ringed ? p.min_ringed_border_share : p.min_clean_border_share)) return 0;
  fill_levels(cs);
  // clearance_sigmas of the ground's own roughness, within [min_clearance, ground_clearance].
  float drop = p.clearance_sigmas * sigma;
  drop = drop < p.min_clearance ? p.min_clearance : (drop > p.ground_clearance ? p.ground_clearance : drop);
  const Level level{g, plane, cs.mean};
  // Terrain is the lowest surface: a flat part of an object (a hood, a
  // pickup's bed) has the rest of the object below it.
  const float below = -(p.below_terrain_sigmas * sigma > p.min_below_terrain ? p.below_terrain_sigmas * sigma
                                                                             : p.min_below_terrain);
  float* tops = scratch + 4u * kTerrainCells;
  const BandCounts counts = column_tops(xyz, n, level, drop, below, tops);
  if (static_cast<float>(counts.near) < p.min_object_ground_share * static_cast<float>(n) ||
      static_cast<float>(counts.under) > p.max_below_terrain_share * static_cast<float>(n) ||
      (ringed && counts.highest < p.min_body_rise))
    return 0;
  float top[2] = {0.0f, 0.0f};  // the two highest kept points above their terrain
  const uint32_t kept = keep_above_band(xyz, n, level, drop, p, tops, top);
  if (terrain != nullptr && kept > 1u) *terrain = TerrainUnder{true, top[1], sigma, drop};
  return n - kept;
}

}  // namespace spinhash
