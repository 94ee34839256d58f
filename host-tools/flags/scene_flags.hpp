// The scene's settings on the command line (scene, survey): one option per
// entry of SPINHASH_SCENE_CONFIG_FIELDS (spinhash/scene_fields.h) that names
// a flag, checked against the entry's range (the core's).
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "spinhash/scene.hpp"

namespace spinhash::flags {

// Every flagged field, or only those whose flag is in `only` when given.
void add_scene_flags(CLI::App* cmd, SceneConfig* cfg, const std::vector<std::string>& only = {});

}  // namespace spinhash::flags
