// spinhash.Result and spinhash.SceneObject: plain Python values copied out
// of the core's answers (whose arrays live in the workspace only until the
// next call), with the words and numbers of the CLI's JSON.
#pragma once
#include <pybind11/pybind11.h>

#include <vector>

#include "spinhash/recognizer.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::python {

// A Result with its ranking copied out of the workspace (ranking == nullptr).
struct ResultCopy {
  Result result;
  std::vector<RankedModel> ranking;
  std::vector<RankedClass> classes;  // class_ranking
  std::vector<RankedGroup> groups;   // group_ranking
  double time_ms = 0.0;
};
ResultCopy copy_result(const Result& r, double time_ms);

struct PyResult {
  pybind11::str status;    // "ok", "empty_cloud", ... (the CLI's words)
  pybind11::object error;  // the core's message when status is not "ok", else None
  pybind11::list ranking;  // (model name, score), best first
  pybind11::object pose;   // 4x4 float64 of the best model, or None (SIND, nothing found)
  bool confident = false;
  uint32_t group_size = 0;         // Result::group_size
  pybind11::object vehicle_class;  // the first class's name (the CLI's "class"), or None
  bool class_confident = false;
  pybind11::list class_ranking;  // (class name, score, model name), best first
  pybind11::object group;        // the first group's name (the CLI's "group"), or None
  pybind11::list group_ranking;  // (group name, score, model name), best first
  pybind11::dict levels;         // {"vehicle": {"confident":.., "evidence":..}, ...} (the CLI's "levels")
  pybind11::str level;           // the CLI's "level": "model", "class", "group", "vehicle" or "none"
  pybind11::dict stats;          // SPINHASH_STATS_FIELDS under the CLI's JSON keys
  double time_ms = 0.0;
};
PyResult make_result(const Database& db, const ResultCopy& r);

// A scene object with its ranking copied out of the workspace.
struct SceneObjectCopy {
  SceneObject object;
  std::vector<RankedModel> ranking;
};

struct PySceneObject {
  pybind11::str kind;      // "vehicle", "too small", ... (object_kind_name)
  pybind11::str status;    // of its recognition ("ok" when not recognised)
  pybind11::object model;  // best model's name (vehicles), else None
  pybind11::object score;  // its score, else None
  pybind11::list ranking;  // (model name, score), best first
  pybind11::object pose;   // 4x4 float64, or None
  bool confident = false;
  uint32_t group_size = 0;
  pybind11::object vehicle_class;  // as PyResult
  bool class_confident = false;
  pybind11::list class_ranking;
  pybind11::object group;        // the first group's name (the CLI's "group"), or None
  pybind11::list group_ranking;  // (group name, score, model name), best first
  pybind11::dict levels;         // {"vehicle": {"confident":.., "evidence":..}, ...} (the CLI's "levels")
  pybind11::str level;           // the CLI's "level": "model", "class", "group", "vehicle" or "none"
  pybind11::object ground_gap;   // m: best model's bottom above the terrain, or None
  uint32_t points = 0;
  pybind11::tuple center;  // georeferenced footprint centre, z mid-height
  pybind11::tuple extent;  // m: length, width, height above terrain
  double heading_deg = 0.0;
};
PySceneObject make_scene_object(const Database& db, const SceneObjectCopy& o);

}  // namespace spinhash::python
