// How much of a model a scan shows under a pose (research measure, not in the
// core): the share of the model's features above its ground band that lie
// within a radius of a query point. docs/results.md 11l asks whether the
// confidence margin should grow as this falls (an occluder hiding what tells
// two touring cars apart).
#pragma once
#include <vector>

#include "spinhash/database.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash::experiment {

constexpr float kCoverageBand = 0.5f;     // m above the model box's bottom: wheels and ground left out
constexpr float kCoverageRadius = 0.25f;  // m: beyond the 0.15 m spacing and 10 cm noise swept

// Share in [0, 1] of model `model`'s features more than kCoverageBand above its
// box bottom with a query point (xyz, 3 per point, the query's frame) within
// kCoverageRadius under `pose` (model frame -> query frame); 0 without such
// features.
float model_coverage(const Database& db, uint32_t model, const Pose& pose, const std::vector<double>& xyz);

}  // namespace spinhash::experiment
