// One survey task: the tile with its neighbours' buffer through the
// streaming scene stage, keeping the objects the tile owns (task.hpp), each
// written as its JSON line and, for vehicle candidates, its GeoJSON feature.
#pragma once
#include <vector>

#include "pipeline/tile_stream_order.hpp"
#include "spinhash/scene.hpp"
#include "spinhash/scene_ownership.hpp"
#include "survey/task.hpp"
#include "survey/tile_result.hpp"

namespace spinhash::survey {

// The areas that may own the task's objects: the cores of its tile and of
// its neighbours, in path order (the tie rule of owner_of,
// spinhash/scene_ownership.hpp); *self: the tile's index among them. With
// kGapTolerance as the tolerance, each tile decides alone and all agree.
std::vector<OwnedArea> owner_areas(const SurveyTask& task, uint32_t* self);

// Throws host::CloudError when the tile or a neighbour cannot be read,
// std::runtime_error when PROJ refuses the CRS or temporary files fail.
TileResult run_task(const Database& db, const SurveyTask& task, const SceneConfig& scene,
                    size_t order_memory_points = pipeline::kOrderMemoryPoints);

}  // namespace spinhash::survey
