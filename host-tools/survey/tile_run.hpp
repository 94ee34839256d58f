// One survey task: the tile with its neighbours' buffer through the
// streaming scene stage, keeping the objects the tile owns (task.hpp), each
// written as its JSON line and, for vehicle candidates, its GeoJSON feature.
#pragma once
#include "spinhash/scene.hpp"
#include "survey/task.hpp"
#include "survey/tile_result.hpp"

namespace spinhash::survey {

// Throws host::CloudError when the tile or a neighbour cannot be read,
// std::runtime_error when PROJ refuses the CRS or temporary files fail.
TileResult run_task(const Database& db, const SurveyTask& task, const SceneConfig& scene);

}  // namespace spinhash::survey
