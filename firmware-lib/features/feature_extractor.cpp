// Orchestrates the feature pipeline over buffers carved once from the arena.
#include <new>

#include "descriptor/spin_images.hpp"
#include "geometry/cell_grid.hpp"
#include "geometry/normals.hpp"
#include "geometry/object_ground.hpp"
#include "geometry/resample.hpp"
#include "kernels/spin_select.hpp"
#include "spinhash/features.hpp"
#include "spinhash/limits.hpp"
#include "util/angle_math.hpp"

namespace spinhash {

struct FeatureExtractor::Impl {
  CellGrid voxel_grid;         // density voxels, then basis voxels
  CellGrid neighbour_grid;     // radius searches over the equalised points
  float* points = nullptr;     // re-centred input, 3 * max_points
  float* equalised = nullptr;  // 3 * max_points
  float* normals = nullptr;    // 3 * max_points
  uint8_t* has_normal = nullptr;
  uint32_t* basis = nullptr;         // max_points
  float* terrain_scratch = nullptr;  // kObjectGroundScratchFloats, when ground is removed
  uint32_t loaded = 0;               // points in `points` after load() and drop_ground()
  float* out_positions = nullptr;
  float* out_normals = nullptr;
  float* out_spins = nullptr;
};

namespace {

bool params_valid(const FeatureParams& p, const ExtractorCapacity& cap) {
  auto positive = [](float v) { return v > 0.0f && v < 1e6f; };
  return positive(p.cloud_voxel) && positive(p.normal_radius) && positive(p.basis_spacing) &&
         positive(p.support_radius) && p.bins_alpha >= 1u && p.bins_beta >= 1u &&
         p.bins_alpha <= kMaxSpinBinsPerAxis && p.bins_beta <= kMaxSpinBinsPerAxis &&
         spin_dims(p) <= cap.max_spin_dims && p.support_angle_deg > 0.0f && cap.max_points >= 1u &&
         cap.max_points <= kMaxQueryPointsLimit && cap.max_features >= 1u;
}

// A sparse scan (an airborne survey at 10-30 points per m^2): fewer than
// min_oriented_share of its points find the kMinNormalNeighbours a normal
// needs within normal_radius. Its normals are estimated again over a radius
// normal_radius_growth times larger, at most max_radius_steps times. Dense
// scans (0.10 m spacing, occluded, noisy: 99.5 % oriented) and the model
// scans keep the database's radius. Returns the radius, *oriented the count.
float sparse_aware_normals(CellGrid& grid, const float* points, uint32_t n, float radius, float* normals,
                           uint8_t* has_normal, const NeighbourScratch& scratch, const ExtractParams& p,
                           uint32_t* oriented) {
  for (uint32_t step = 0;; ++step, radius *= p.normal_radius_growth) {
    // The voxel grid at the radius makes the PCA searches visit 27 cells.
    grid.build(points, n, radius);
    *oriented = estimate_normals(grid, points, n, radius, normals, has_normal, scratch);
    if (step >= p.max_radius_steps ||
        static_cast<float>(*oriented) >= p.min_oriented_share * static_cast<float>(n))
      return radius;
  }
}

SpinImageParams spin_params(const FeatureParams& p) {
  SpinImageParams sp;
  sp.radius = p.support_radius;
  sp.bins_alpha = p.bins_alpha;
  sp.bins_beta = p.bins_beta;
  sp.use_support_angle = p.support_angle_deg < 180.0f;
  sp.cos_support_angle = std::cos(deg_to_rad(p.support_angle_deg));
  return sp;
}

// The spin images' gathered neighbourhoods (descriptor/spin_images.hpp) in
// the re-centred input's 3 * max_points floats, free once the points are
// equalised: max_points places in the basis, then six arrays of the
// rest. Only when a SIMD spin kernel is built: the reference walks the grid.
constexpr uint32_t kSpinScratchArrays = 6;  // x, y, z, nx, ny, nz
SpinScratch spin_scratch(float* free_floats, uint32_t max_points) {
  SpinScratch s;
  if (!kernels::kSpinGathers) return s;
  // The arena's bytes hold floats or indices (both 4 bytes), as the normals' scratch does.
  static_assert(sizeof(float) == sizeof(uint32_t), "4-byte floats and indices");
  s.basis_of = reinterpret_cast<uint32_t*>(free_floats);
  s.capacity = 2u * max_points / kSpinScratchArrays;
  s.x = free_floats + max_points;
  s.y = s.x + s.capacity;
  s.z = s.y + s.capacity;
  s.nx = s.z + s.capacity;
  s.ny = s.nx + s.capacity;
  s.nz = s.ny + s.capacity;
  return s;
}

}  // namespace

Status FeatureExtractor::init(const FeatureParams& params, const ExtractorCapacity& cap,
                              Arena& arena) noexcept {
  if (!params_valid(params, cap)) return Status::kInvalidArgument;
  params_ = params;
  cap_ = cap;
  Impl* impl = arena.alloc<Impl>(1);
  Impl scratch;  // counting arenas give no memory: carve into a throw-away
  Impl* target = impl != nullptr ? new (impl) Impl() : &scratch;
  const uint32_t np = cap.max_points, nf = cap.max_features;
  target->voxel_grid.carve(arena, np);
  target->neighbour_grid.carve(arena, np);
  target->points = arena.alloc<float>(3u * static_cast<size_t>(np));
  target->equalised = arena.alloc<float>(3u * static_cast<size_t>(np));
  target->normals = arena.alloc<float>(3u * static_cast<size_t>(np));
  target->has_normal = arena.alloc<uint8_t>(np);
  target->basis = arena.alloc<uint32_t>(np);
  if (cap.drops_ground) target->terrain_scratch = arena.alloc<float>(kObjectGroundScratchFloats);
  target->out_positions = arena.alloc<float>(3u * static_cast<size_t>(nf));
  target->out_normals = arena.alloc<float>(3u * static_cast<size_t>(nf));
  target->out_spins = arena.alloc<float>(static_cast<size_t>(nf) * cap.max_spin_dims);
  if (arena.overflowed()) return Status::kWorkspaceTooSmall;
  impl_ = impl;
  return Status::kOk;
}

Status FeatureExtractor::extract(const CloudView& cloud, const OrientationHint& hint, FeatureSet* out,
                                 ExtractStats* stats) noexcept {
  const Status s = load(cloud, out, stats);
  return s != Status::kOk ? s : describe(hint, ExtractParams{}, cap_.max_features, out, stats);
}

Status FeatureExtractor::load(const CloudView& cloud, FeatureSet* out, ExtractStats* stats) noexcept {
  if (impl_ == nullptr || out == nullptr || stats == nullptr) return Status::kNotOpen;
  impl_->loaded = 0;
  if ((cloud.xyz_f == nullptr) == (cloud.xyz_d == nullptr) && cloud.count > 0)
    return Status::kInvalidArgument;
  *stats = ExtractStats{};
  *out = FeatureSet{};
  stats->points_in = cloud.count;
  if (cloud.count > cap_.max_points && !cap_.thin_large_clouds) return Status::kTooManyPoints;
  Impl& m = *impl_;
  const uint32_t keep = cloud.count > cap_.max_points ? cap_.max_points : cloud.count;
  stats->points_thinned = cloud.count - keep;
  const uint32_t n = recentre(cloud, keep, out->origin, m.points);
  stats->points_nonfinite = keep - n;
  m.loaded = n;
  return n == 0 ? Status::kEmptyCloud : Status::kOk;
}

Status FeatureExtractor::drop_ground(const GroundParams& params, FeatureSet* out,
                                     uint32_t* dropped) noexcept {
  if (impl_ == nullptr || out == nullptr || dropped == nullptr) return Status::kNotOpen;
  Impl& m = *impl_;
  *dropped = 0;
  if (m.terrain_scratch == nullptr) return Status::kOk;  // sized without room for the terrain grid
  TerrainUnder terrain;
  *dropped = remove_object_ground(m.points, m.loaded, params, m.terrain_scratch, &terrain);
  m.loaded -= *dropped;
  if (m.loaded == 0) return Status::kNotEnoughFeatures;  // nothing stands on the ground
  if (terrain.found) {
    out->top_above_terrain = terrain.top;
    out->terrain_sigma = terrain.sigma;
    out->ground_band = terrain.band;
  }
  return Status::kOk;
}

Status FeatureExtractor::describe(const OrientationHint& hint, const ExtractParams& params,
                                  uint32_t max_features, FeatureSet* out, ExtractStats* stats,
                                  uint32_t max_equalised) noexcept {
  if (impl_ == nullptr || out == nullptr || stats == nullptr) return Status::kNotOpen;
  Impl& m = *impl_;
  const uint32_t n = m.loaded;
  if (n == 0) return Status::kEmptyCloud;
  const float cloud_voxel = params.query_cloud_voxel > 0.0f ? params.query_cloud_voxel : params_.cloud_voxel;
  const float basis_spacing =
      params.query_basis_spacing > 0.0f ? params.query_basis_spacing : params_.basis_spacing;

  m.voxel_grid.build(m.points, n, cloud_voxel);
  uint32_t ne = equalise_density(m.voxel_grid, m.points, m.equalised);
  stats->points_equalised = ne;
  if (ne > max_equalised) {
    m.loaded = 0;  // the load is spent either way
    out->count = 0;
    return Status::kWorkCapReached;
  }

  // The voxel grid is free until basis selection; the spin images' output
  // holds the normals' gathered neighbourhoods.
  NeighbourScratch scratch;
  const size_t spin_floats = static_cast<size_t>(cap_.max_features) * cap_.max_spin_dims;
  constexpr size_t kNormalScratchArrays = 3;  // x, y, z
  const size_t room = spin_floats / kNormalScratchArrays;
  scratch.capacity = static_cast<uint32_t>(room < cap_.max_points ? room : cap_.max_points);
  scratch.x = m.out_spins;
  scratch.y = scratch.x + scratch.capacity;
  scratch.z = scratch.y + scratch.capacity;
  const float radius = sparse_aware_normals(m.voxel_grid, m.equalised, ne, params_.normal_radius, m.normals,
                                            m.has_normal, scratch, params, &stats->points_oriented);
  float cell = params_.support_radius * 0.5f;  // spin support R = two cells each way
  if (cell < radius) cell = radius;
  m.neighbour_grid.build(m.equalised, ne, cell);

  float reference[3] = {0.0f, 0.0f, 0.0f};
  if (hint.has_viewpoint) {
    for (int a = 0; a < 3; ++a) reference[a] = static_cast<float>(hint.viewpoint[a] - out->origin[a]);
  } else {
    for (uint32_t i = 0; i < ne; ++i)
      for (int a = 0; a < 3; ++a) reference[a] += m.equalised[3u * i + a];
    for (int a = 0; a < 3; ++a) reference[a] /= static_cast<float>(ne);
  }
  orient_normals(m.equalised, ne, reference, hint.has_viewpoint, m.normals, m.has_normal);

  m.voxel_grid.build(m.equalised, ne, basis_spacing);
  uint32_t nb = select_basis_points(m.voxel_grid, m.equalised, m.has_normal, m.basis);
  stats->basis_points = nb;
  const uint32_t keep = max_features < cap_.max_features ? max_features : cap_.max_features;
  stats->features_thinned = nb > keep;
  nb = thin_evenly(m.basis, nb, keep);

  const SpinImageParams sp = spin_params(params_);
  const uint32_t dims = spin_dims(params_);
  for (uint32_t k = 0; k < nb; ++k) {
    for (int a = 0; a < 3; ++a) {
      m.out_positions[3u * k + a] = m.equalised[3u * m.basis[k] + a];
      m.out_normals[3u * k + a] = m.normals[3u * m.basis[k] + a];
    }
  }
  compute_spin_images(sp, m.neighbour_grid, m.equalised, ne, m.normals, m.has_normal, m.basis, nb,
                      spin_scratch(m.points, cap_.max_points), m.out_spins);
  m.loaded = 0;  // the spin images' scratch has overwritten the loaded points
  stats->features = nb;
  out->count = nb;
  out->dims = dims;
  out->positions = m.out_positions;
  out->normals = m.out_normals;
  out->spins = m.out_spins;
  return Status::kOk;
}

}  // namespace spinhash
