// One recognition answer made visible: the query's points and the best
// model's stored points (the database's feature positions: the blob holds no
// mesh) in its recognised pose, both in the query's georeferenced frame.
// Written as a coloured PLY (query grey-blue, model orange) and drawn as a
// PNG, top-down and side-on (render/answer_picture.hpp).
#pragma once

#include <string>
#include <vector>

#include "spinhash/recognizer.hpp"

namespace spinhash::pipeline {

struct AnswerOverlay {
  std::vector<double> query;  // the finite query points, as read
  std::vector<double> model;  // the best model's points, posed (empty without a pose)
  std::string model_name;     // empty when nothing was ranked
  bool confident = false;
  double heading[2] = {1.0, 0.0};  // the posed model's x axis in the ground plane: the side view's axis
};

// From a query and its result: the model is ranking[0], when it has a pose.
AnswerOverlay make_answer_overlay(const Database& db, const std::vector<double>& query, const Result& r);

// FILE.ply: the query's points then the model's, coloured.
bool write_overlay_ply(const std::string& path, const AnswerOverlay& o, std::string* error);
// FILE.png: top-down and side-on, titled with the query, the model and whether it is confident.
bool write_overlay_picture(const std::string& path, const std::string& query_name, const AnswerOverlay& o,
                           std::string* error);

}  // namespace spinhash::pipeline
