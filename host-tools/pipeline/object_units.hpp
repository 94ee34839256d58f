// A scene object found in metres, its georeferenced fields back in the
// file's units (cloud/crs_units.hpp): the centre and the ranking's pose
// translations. Sizes (extent, heights, ground_gap) stay in metres, as the
// gates and the models are; a pose's rotation acts on the model's metres.
#pragma once

#include <vector>

#include "cloud/crs_units.hpp"
#include "spinhash/recognizer.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::pipeline {

// o with its centre and pose translations divided by the units; the
// ranking is copied to *ranking, which the result points into.
SceneObject in_file_units(const SceneObject& o, const host::AxisUnits& units,
                          std::vector<RankedModel>* ranking);
// The same for a recognition's result (spinhash recognize).
Result in_file_units(const Result& r, const host::AxisUnits& units, std::vector<RankedModel>* ranking);

}  // namespace spinhash::pipeline
