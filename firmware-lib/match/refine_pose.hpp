// Least-squares refinement of a hypothesis: the pose from two doublets
// carries their sampling and normal noise; re-estimating it from every query
// feature that the pose matches within Delta (Kabsch over their positions and
// normal tips) tightens it, and with it the likelihood that separates
// look-alike models. Not in the paper; applied to the best few models only.
#pragma once
#include "match/likelihood.hpp"

namespace spinhash {

constexpr uint32_t kMinRefineMatches = 3;  // fewer inliers: keep the pose as it is

// Replaces *pose with the refined one; false (pose untouched) when too few matches.
bool refine_pose(const Database& db, uint32_t model, const QueryFeatures& query, const LikelihoodParams& lp,
                 RigidPose* pose);

}  // namespace spinhash
