// The vehicle class of each database model (blob format 4), given at build
// time: by a manifest, by the folder a mesh lies in, or by its name.
#pragma once
#include <string>
#include <vector>

#include "pipeline/model_sources.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::pipeline {

// The class a model name starts with, before its first '-' or '_'
// ("sedan-03", "apc_2"; the procedural fleet's family-index names), or
// unclassified.
VehicleClass class_from_name(const std::string& name);
// A mesh file's class: its folder's name when that is a class
// ("meshes/pickup/hilux.obj"), else class_from_name of its stem.
VehicleClass class_of_file(const std::string& path);

// Reads a manifest, one "MODEL_NAME CLASS [GROUP]" a line ('#' starts a
// comment), and sets the class of each model it names, and its own group
// (only for a class in no group: an "other" buggy is "light"; a class in a
// group may repeat its own). False, with one line per problem in *error,
// for an unknown class or group, a group the class contradicts, a model
// not among `models`, a model named twice or a line that is not two or
// three words.
bool apply_class_manifest(const std::string& path, std::vector<host::ModelCloud>* models, std::string* error);

}  // namespace spinhash::pipeline
