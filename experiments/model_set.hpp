// The models of an experiment: the procedural fleet (in memory) or mesh
// files, and their model clouds (the paper's 8-view scans).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/model_sources.hpp"

namespace spinhash::experiment {

// `count` procedural vehicles (member i of the fleet for any count is the
// same vehicle, so smaller fleets are prefixes of larger ones).
std::vector<pipeline::ModelMesh> generated_models(uint32_t count, uint64_t fleet_seed);

// Meshes from files/directories; at most max_count (0: all), in name order.
bool loaded_models(const std::vector<std::string>& inputs, uint32_t max_count,
                   std::vector<pipeline::ModelMesh>* out, std::string* error);

// Model clouds with the database builder's default ray spacing.
bool model_clouds(const std::vector<pipeline::ModelMesh>& meshes, std::vector<host::ModelCloud>* out,
                  std::string* error);

}  // namespace spinhash::experiment
