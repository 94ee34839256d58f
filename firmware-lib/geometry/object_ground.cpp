#include "geometry/object_ground.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>

#include "util/angle_math.hpp"
#include "util/heap_sort.hpp"

namespace spinhash {
namespace {

constexpr float kEmptyCell = 3.0e38f;  // lowest point of a cell without points
constexpr uint32_t kMinPlaneCells = 3;
// CellStats::spread of a cell without kMinRoughnessPoints ground points: none
// (kUnmeasured), or a few, all within kRoughnessBand of its low lowest point
// (kSparseFlat: ground a sparse scan samples thinly, issue 28: at 10-20
// points per m^2 the 1 m cells the footprint's edge cuts hold 1-4 points, and
// two thirds of the border cells of a vehicle on open ground were not
// measured, so its ground was never removed).
constexpr float kUnmeasured = -1.0f;
constexpr float kSparseFlat = -2.0f;
// A sparse scan's terrain shows at least this many cells of measured, clean
// ground: bare vehicles scanned at 12-32 points per m^2 show 0-18 (a
// truck's box roof the most), and a pickup's roof, hood and bed passed
// every other test (it lost 75 % of its points as "ground" before this);
// with a 12 m ground square around them 27-147.
constexpr uint32_t kMinSparseGroundCells = 24;
// Fewer clean cells are terrain when they ring the footprint and a body
// stands on them: a survey's cut-out of a car reaching a metre or two past
// it shows 13-23 clean cells at 12-21 points per m^2, 95-100 % of the
// border clean and the roof 1.5-2.2 m above; 22 of 24 sedans there kept
// their ground and were named tracked vehicles or buses (issue 28).
// Bare vehicles fail one of the two: a sedan's or a pickup's top rings its
// footprint (border up to 100 % clean) with nothing 0.85 m above it, a
// truck's cab roof has its box 2.3 m above but at most 79 % of the border.
constexpr uint32_t kMinRingedGroundCells = 12;
constexpr float kMinRingedBorderShare = 0.9f;
constexpr float kMinBodyRise = 1.0f;  // m above the terrain: a vehicle stands there
// A dense scan's terrain shows at least this many m^2 of measured, clean
// ground. Without ground, a low open-wheel racer (TORCS' car1-ow1, 4.5 x
// 1.4 x 0.85 m) scanned noise-free at 0.05-0.10 m shows 23-27 clean 0.5 m
// cells (5.8-6.8 m^2) whose spread, its bodywork's slopes within a cell,
// reads as 10 cm of noise (sigma 0.09-0.10 m): 85 % of its points went as
// "ground" and it was named a touring car (issue 28). The same cars on a
// 6.4 m ground square show 91-148 cells (23-37 m^2); the tests' ground
// patches reach 4.5 m or more around the vehicle.
constexpr float kMinDenseGroundArea = 10.0f;

struct Grid {
  float x0 = 0.0f, y0 = 0.0f, cell = kMinTerrainCell;
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

Grid footprint(const float* xyz, uint32_t n) {
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
  g.cell = cell > kMinTerrainCell ? cell : kMinTerrainCell;
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

bool fit_terrain_plane(const Grid& g, const float* lowest, Plane* plane) {
  if (!fit_plane(g, lowest, nullptr, 0.0f, plane)) return false;
  for (uint32_t round = 1; round < kTerrainFitRounds; ++round) {
    const Plane previous = *plane;
    const float rise = round <= kTerrainCoarseRounds ? kObjectCellRise : kGroundCellRise;
    if (!fit_plane(g, lowest, &previous, rise, plane)) return false;
  }
  return std::sqrt(plane->a * plane->a + plane->b * plane->b) <= std::tan(deg_to_rad(kMaxTerrainSlopeDeg));
}

// Per cell, over its ground points (those within kRoughnessBand of the
// lowest point of a cell that rises at most kGroundCellRise above the
// plane): their mean height above the plane and their spread.
struct CellStats {
  float* mean;    // level: becomes the cell's ground level
  float* spread;  // sigma of the ground points; < 0: no usable ground
  float* count;   // points; then scratch for the median
};

void accumulate(const float* xyz, uint32_t n, const Grid& g, const Plane& plane, const float* lowest,
                const CellStats& cs) {
  for (uint32_t c = 0; c < kTerrainCells; ++c) cs.mean[c] = cs.spread[c] = cs.count[c] = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    const float* p = xyz + 3u * i;
    const uint32_t c = g.cell_of(p);
    if (lowest[c] - plane.at(g.centre_x(c), g.centre_y(c)) > kGroundCellRise ||
        p[2] > lowest[c] + kRoughnessBand)
      continue;
    const float d = p[2] - plane.at(p[0], p[1]);
    cs.mean[c] += d;
    cs.spread[c] += d * d;
    cs.count[c] += 1.0f;
  }
  for (uint32_t c = 0; c < kTerrainCells; ++c) {
    if (cs.count[c] < static_cast<float>(kMinRoughnessPoints)) {
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
                        const CellStats& cs) {
  for (uint32_t i = 0; i < n; ++i) {
    const float* p = xyz + 3u * i;
    const uint32_t c = g.cell_of(p);
    if (cs.spread[c] == kSparseFlat && p[2] > lowest[c] + kRoughnessBand) cs.spread[c] = kUnmeasured;
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

// Clean ground cells (spread at most kCleanSpreadFactor x the median)
// flagged in count.
void mark_clean(const CellStats& cs, float sigma) {
  const float clean = kCleanSpreadFactor * sigma + kSpreadSlack;
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
// kMinRingedGroundCells or more), or nothing.
enum class CleanGround { kTerrain, kTerrainIfRinged, kNone };

CleanGround clean_ground(const CellStats& cs, const Grid& g, bool sparse) {
  const uint32_t clean = clean_cells(cs);
  if (!sparse)
    return static_cast<float>(clean) * g.cell * g.cell < kMinDenseGroundArea ? CleanGround::kNone
                                                                             : CleanGround::kTerrain;
  if (clean >= kMinSparseGroundCells) return CleanGround::kTerrain;
  return clean >= kMinRingedGroundCells ? CleanGround::kTerrainIfRinged : CleanGround::kNone;
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
uint32_t keep_above_band(float* xyz, uint32_t n, const Level& level, float drop, const float* tops,
                         float top[2]) {
  const float body = drop + kBodyAbove;           // a column rising this high holds a body
  const float body_floor = kBandKeptFrom * drop;  // band points below it are ground even there
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

uint32_t remove_object_ground(float* xyz, uint32_t n, float clearance, float* scratch,
                              TerrainUnder* terrain) {
  if (terrain != nullptr) *terrain = TerrainUnder{};
  if (n == 0 || !(clearance > 0.0f)) return 0;
  float* lowest = scratch;
  const CellStats cs{scratch + kTerrainCells, scratch + 2u * kTerrainCells, scratch + 3u * kTerrainCells};
  Grid g = footprint(xyz, n);
  lowest_points(xyz, n, g, lowest);
  uint32_t occupied = occupied_cells(lowest);
  // A sparse scan: cells scaled so that they hold kMinPointsPerCell points
  // on average (the occupied area grows with the cell too, so this is a lower
  // bound on the scale), once, up to kMaxTerrainCell. The grid keeps its
  // corner; the larger cell still covers the footprint.
  const float per_cell = static_cast<float>(n) / static_cast<float>(occupied > 0u ? occupied : 1u);
  if (per_cell < kMinPointsPerCell && g.cell < kMaxTerrainCell) {
    const float wanted = g.cell * std::sqrt(kMinPointsPerCell / per_cell);
    g.cell = wanted < kMaxTerrainCell ? wanted : kMaxTerrainCell;
    lowest_points(xyz, n, g, lowest);
    occupied = occupied_cells(lowest);
  }
  Plane plane;
  if (!fit_terrain_plane(g, lowest, &plane)) return 0;
  uint32_t ground_cells = 0;
  accumulate(xyz, n, g, plane, lowest, cs);
  const float sigma = median_spread(cs, &ground_cells);
  if (static_cast<float>(ground_cells) < kMinGroundCellShare * static_cast<float>(occupied) ||
      sigma > kMaxGroundRoughness)
    return 0;
  mark_clean(cs, sigma);
  const bool sparse = g.cell > kMinTerrainCell;  // cells grown for a sparse scan
  const CleanGround proof = clean_ground(cs, g, sparse);
  if (proof == CleanGround::kNone) return 0;
  const bool ringed = proof == CleanGround::kTerrainIfRinged;
  unflatten_occupied(xyz, n, g, lowest, cs);
  const float border = clean_border_share(lowest, cs, sparse);
  if (border < (ringed ? kMinRingedBorderShare : kMinCleanBorderShare)) return 0;
  fill_levels(cs);
  // kClearanceSigmas of the ground's own roughness, within [kMinClearance, clearance].
  float drop = kClearanceSigmas * sigma;
  drop = drop < kMinClearance ? kMinClearance : (drop > clearance ? clearance : drop);
  const Level level{g, plane, cs.mean};
  // Terrain is the lowest surface: a flat part of an object (a hood, a
  // pickup's bed) has the rest of the object below it.
  const float below =
      -(kBelowTerrainSigmas * sigma > kMinBelowTerrain ? kBelowTerrainSigmas * sigma : kMinBelowTerrain);
  float* tops = scratch + 4u * kTerrainCells;
  const BandCounts counts = column_tops(xyz, n, level, drop, below, tops);
  if (static_cast<float>(counts.near) < kMinObjectGroundShare * static_cast<float>(n) ||
      static_cast<float>(counts.under) > kMaxBelowTerrainShare * static_cast<float>(n) ||
      (ringed && counts.highest < kMinBodyRise))
    return 0;
  float top[2] = {0.0f, 0.0f};  // the two highest kept points above their terrain
  const uint32_t kept = keep_above_band(xyz, n, level, drop, tops, top);
  if (terrain != nullptr && kept > 1u) *terrain = TerrainUnder{true, top[1], sigma, drop};
  return n - kept;
}

}  // namespace spinhash
