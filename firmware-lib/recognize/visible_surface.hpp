// The other half of the fit (not in the paper): eq. 7 scores how well a
// model explains the query, never whether the query shows what the model
// would have shown. A longer bus explains every point of a shorter one's
// scan, so larger look-alikes win. From the air the roof, the hood and the
// deck face the sensor whatever the side scanned: every model feature facing
// up under the pose (RefineParams::upward_normal_z) should have query
// features within Delta: each one is seen or missed (log_seen, log_missed).
// The share seen is also the first model's surface_coverage, which the
// confidence margin reads (confidence.hpp). Bounded: for each of the
// rescored leaders, the lent look-alikes and the first model once more, the
// model's features x the query features in at most 8 cells of a grid twice
// Delta wide (found in the query features' grid, built once per query).
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

// What the scan shows of the model's upward surface under `pose`: each
// upward model feature seen (a query feature within Delta) or missed.
struct UpwardSurface {
  float log_likelihood = 0.0f;  // of the features seen and missed
  uint32_t facing = 0;          // model features facing up under the pose
  uint32_t seen = 0;            // of those, with a query feature within Delta
  // The share seen (ConfidenceStats::surface_coverage); 0 when none faces up.
  float coverage() const { return facing ? static_cast<float>(seen) / static_cast<float>(facing) : 0.0f; }
};
UpwardSurface upward_surface(const SearchContext& ctx, uint32_t model, const RigidPose& pose);
// Indexes the query features for upward_surface (once per query).
void index_query_features(SearchContext& ctx);

}  // namespace spinhash
