// A scene object as the outlined, labelled box of the pictures (a tile's,
// `scene --picture-out`, and a survey's overview): the model (with "?" when
// not confident) on vehicle candidates, what it is on the others.
#pragma once
#include "render/tile_picture.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::pipeline {

// o's centre in the tile's units, its extent in metres (metres_per_unit:
// pipeline/object_units.hpp).
host::PictureBox object_box(const Database& db, const SceneObject& o, double metres_per_unit = 1.0);

}  // namespace spinhash::pipeline
