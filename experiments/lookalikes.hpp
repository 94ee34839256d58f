// Databases full of near-identical models: each model's stretched,
// shortened, widened, narrowed and mirrored copies (what real vehicle
// libraries hold: the same body in several lengths, left- and right-hand
// versions). Queries still come from the originals, which must be told apart
// from copies a few centimetres longer or mirrored.
#pragma once
#include <cstdint>
#include <vector>

#include "pipeline/model_sources.hpp"

namespace spinhash::experiment {

// Relative size step between successive copies of one kind: 3% of a 4.5 m
// car is 13.5 cm, about the scan noise at 10 cm spacing.
constexpr double kLookalikeStep = 0.03;
constexpr uint32_t kMaxLookalikesPerModel = 64;

// The originals first (same indices), then `copies` rounds of one copy of
// each (so any prefix holds every model's copies evenly), named
// "<model>~<kind><level>": sx+ / sx- stretch or shorten along x (length),
// sy+ / sy- along y (width), m mirrored in y (and stretched by level - 1
// steps). Copy k of a model is kind (k mod 5) at level (k / 5) + 1.
std::vector<pipeline::ModelMesh> with_lookalikes(const std::vector<pipeline::ModelMesh>& originals,
                                                 uint32_t copies);

}  // namespace spinhash::experiment
