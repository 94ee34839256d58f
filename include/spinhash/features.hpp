// Oriented spin-image features from a point cloud: the one code path used for
// database models (host build) and for queries (onboard), so the two can never
// drift apart. Pipeline: re-centre in double, drop non-finite points, (for a
// query, drop its ground: the recognizer's ground stage), voxel equalise
// density, PCA normals, consistent orientation, uniform basis points, spin
// images.
#pragma once
#include <cstddef>
#include <cstdint>

#include "spinhash/arena.hpp"
#include "spinhash/config.hpp"
#include "spinhash/status.hpp"

namespace spinhash {

// Points as float or double xyz triples (exactly one of the two set).
struct CloudView {
  const float* xyz_f = nullptr;
  const double* xyz_d = nullptr;
  uint32_t count = 0;
};

// Capacities that size the extractor's share of a workspace.
struct ExtractorCapacity {
  uint32_t max_points = 32768;    // raw points accepted
  uint32_t max_features = 1024;   // basis points kept (deterministically thinned above)
  uint32_t max_spin_dims = 256;   // bins_alpha * bins_beta supported
  bool thin_large_clouds = true;  // above max_points: keep max_points spread evenly (else refuse)
  bool drops_ground = false;      // room for drop_ground's terrain grid (queries)
};

// Normal orientation (z up): within 45 degrees of level, up; steeper, away
// from the vertical through the cloud centroid; or towards a viewpoint.
struct OrientationHint {
  bool has_viewpoint = false;
  double viewpoint[3] = {0.0, 0.0, 0.0};  // input coordinates
};

// Features live in the arena; positions are relative to `origin`.
struct FeatureSet {
  uint32_t count = 0;
  uint32_t dims = 0;           // d = bins_alpha * bins_beta
  float* positions = nullptr;  // 3 per feature
  float* normals = nullptr;    // 3 per feature, unit length
  float* spins = nullptr;      // dims per feature, normalised to sum 1
  double origin[3] = {0.0, 0.0, 0.0};
  // The terrain the object stands on, when drop_ground found and dropped it
  // (GroundParams): the object's top above it (the
  // second highest point; m), the ground's roughness (m, the scan's noise) and
  // the band above the terrain dropped with it (m: the object's lowest part,
  // a low nose or bumper, went too). top_above_terrain < 0: no terrain found.
  float top_above_terrain = -1.0f;
  float terrain_sigma = 0.0f;
  float ground_band = 0.0f;
};

struct ExtractStats {
  uint32_t points_in = 0;
  uint32_t points_thinned = 0;    // dropped to fit max_points (evenly spread)
  uint32_t points_nonfinite = 0;  // dropped NaN / infinite / beyond 1e9 m points (of those kept)
  uint32_t points_equalised = 0;  // after the density voxel
  uint32_t points_oriented = 0;   // with a usable normal
  uint32_t basis_points = 0;      // before thinning to max_features
  bool features_thinned = false;  // more basis points than max_features
  uint32_t features = 0;          // s: features described (basis points kept)
};

// Buffers reserved once; the same object is reused for every cloud.
class FeatureExtractor {
 public:
  // Carves its buffers from `arena` (counting arenas work too).
  Status init(const FeatureParams& params, const ExtractorCapacity& cap, Arena& arena) noexcept;
  // The whole path without ground removal (the database's models): load,
  // then describe with the default ExtractParams.
  Status extract(const CloudView& cloud, const OrientationHint& hint, FeatureSet* out,
                 ExtractStats* stats) noexcept;

  // The same path in steps (the recognizer's ground and extract stages).
  // Re-centres the cloud, thins it to max_points and drops its non-finite
  // points; *out and *stats start afresh (out->origin is set).
  Status load(const CloudView& cloud, FeatureSet* out, ExtractStats* stats) noexcept;
  // Drops the terrain under the loaded points (geometry/object_ground.hpp)
  // and records it in out's terrain fields; *dropped: how many points went.
  // Needs ExtractorCapacity::drops_ground. kNotEnoughFeatures when nothing
  // stands on the ground.
  Status drop_ground(const GroundParams& params, FeatureSet* out, uint32_t* dropped) noexcept;
  // The loaded points' features, by `params` (ExtractParams' query_* fields
  // override the database's voxel and spacing), at most `max_features` of
  // them (and at most the capacity's). When the equalised cloud holds more
  // than `max_equalised` points it stops before their normals and spin
  // images (most of the work): kWorkCapReached, no features,
  // stats->points_equalised set (a work cap's bound, recognize/work_meter.hpp).
  Status describe(const OrientationHint& hint, const ExtractParams& params, uint32_t max_features,
                  FeatureSet* out, ExtractStats* stats, uint32_t max_equalised = UINT32_MAX) noexcept;

 private:
  struct Impl;  // buffers, placed in the arena by init()
  FeatureParams params_{};
  ExtractorCapacity cap_{};
  Impl* impl_ = nullptr;
};

}  // namespace spinhash
