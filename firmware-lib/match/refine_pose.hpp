// Least-squares refinement of a hypothesis: the pose from two doublets
// carries their sampling and normal noise; re-estimating it from every query
// feature that the pose matches within Delta tightens it, and with it the
// likelihood that separates look-alike models. Point to plane: each match
// pulls its query feature onto the tangent plane of its model feature, not
// onto the feature itself, which sits anywhere in its basis voxel (up to
// 0.2 m away along the surface at 0.25 m spacing); a Gauss-Newton step of
// the six pose parameters. Not in the paper; applied to the best few models
// only.
#pragma once
#include "match/likelihood.hpp"

namespace spinhash {

// Fewer matches than pose parameters: keep the pose as it is.
constexpr uint32_t kMinRefineMatches = 6;

// Replaces *pose with the refined one; false (pose untouched) when too few
// matches or a non-finite step. `matches`: each query feature's match at
// *pose as verify_pose recorded it (saves the search); null: searched here.
// `damping` per match (m^2, rad^2; RefineParams::damping_per_match): a
// direction no match constrains (sliding along a single flat side) does not
// move, and constrained ones are untouched (their weight is ~0.1-10 per match).
bool refine_pose(const Database& db, uint32_t model, const QueryFeatures& query, const LikelihoodParams& lp,
                 RigidPose* pose, const int32_t* matches, float damping);

// `pose` turned by 180 degrees about the vertical line through the centre of
// the model's box: the other way round on the same footprint. Vehicles are
// nearly symmetric front to back (a bus's flat sides and roof dominate its
// features), so a hypothesis may come the wrong way round, and refinement,
// a local search, stays there.
RigidPose turned_end_to_end(const RigidPose& pose, const blob::ModelRecord& model);

// Pose `index` (< kEndAlignedPoses) of `target` from `source`'s `pose`, for
// a sibling of any length: 0 and 1 with the two boxes' rear ends (x min)
// made to coincide, 2 and 3 with their front ends (x max); 1 and 3 also
// turned end to end (target's front where source's rear was). false for 2
// when its shift is within `min_end_shift` m of 0's (the same pose;
// RefineParams::lend_min_end_shift). A sibling of the same length gets pose
// 0 as it is: the pose the first model ends with (after its focused search
// and refinement) may fit a twin that the draws' own poses never came near.
constexpr uint32_t kEndAlignedPoses = 4;
bool end_aligned_pose(const RigidPose& pose, const blob::ModelRecord& source, const blob::ModelRecord& target,
                      uint32_t index, RigidPose* out, float min_end_shift);

}  // namespace spinhash
