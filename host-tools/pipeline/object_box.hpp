// A scene object as the outlined, labelled box of the pictures (a tile's,
// `scene --picture-out`, and a survey's overview): the model (with "?" when
// not confident) on vehicle candidates, what it is on the others.
#pragma once
#include "render/tile_picture.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::pipeline {

host::PictureBox object_box(const Database& db, const SceneObject& o);

}  // namespace spinhash::pipeline
