// A scene object as the members of `scene`'s JSON line (docs/cli.md). This
// list of keys is the one list that `scene`'s lines and the survey's outputs
// (its JSON lines, the GeoJSON properties and, through them, the GeoPackage's
// columns) are written from.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "spinhash/scene.hpp"

namespace spinhash::pipeline {

struct JsonMember {
  std::string key;
  std::string value;  // raw JSON
};

// The keys of SPINHASH_SCENE_OBJECT_KEYS (spinhash/scene_fields.h), in its
// order: "tile", "object", "kind", "status", "model", "confident",
// "group_size", "class", "class_confident", "class_ranking" (class_json.hpp),
// "group", "group_ranking", "levels", "level" (level_json.hpp), "score", "ranking", "pose", "ground_gap",
// "points", "center", "extent", "heading_deg" (tests/host/test_field_mirrors.cpp checks `scene`'s lines
// against the list, tests/python/test_scene_fields.py Python's SceneObject).
std::vector<JsonMember> object_members(const std::string& tile, uint32_t k, const Database& db,
                                       const SceneObject& o);

// {"key":value,...} in the members' order.
std::string members_json(const std::vector<JsonMember>& members);

// `scene`'s line: the object's members, then "crs" (the tile's, as
// Crs::describe() names it; null when the file declares none), "time_ms"
// and "version".
std::string object_json(const std::string& tile, uint32_t k, const Database& db, const SceneObject& o,
                        const std::string& crs, double time_ms);

// A pose as 16 numbers, row-major 4x4 (translation with 15 digits: georeferenced).
std::string pose_json(const Pose& p);

}  // namespace spinhash::pipeline
