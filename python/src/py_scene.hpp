// What the scene's Python classes share: settings from keywords, statistics as a dict.
#pragma once
#include <pybind11/pybind11.h>

#include "spinhash/scene.hpp"

namespace spinhash::python {

// A SceneConfig from spinhash.Config-style settings plus the scene's own
// (top_n, max_tile_points, max_objects); ValueError/TypeError when invalid.
SceneConfig scene_config_from(const pybind11::object& config, const pybind11::kwargs& kwargs);
pybind11::dict scene_stats_dict(const SceneStats& stats);

// spinhash.AlongTrackOrder (py_scene_order.cpp), bound with SceneStream.
void bind_along_track_order(pybind11::module_& m);

}  // namespace spinhash::python
