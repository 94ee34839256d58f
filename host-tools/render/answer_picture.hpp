// The picture of one recognition answer: the query's points and the posed
// model's points, top-down (x right, y up: north) and side-on (along the
// model's length, z up) at one scale, with a title naming the model and
// whether it is confident, and a 1 m scale bar. A person should see at a
// glance whether the model sits on the query.
#pragma once

#include <string>
#include <vector>

namespace spinhash::host {

struct AnswerPicture {
  const std::vector<double>* query = nullptr;  // x y z per point, any frame (georeferenced is fine)
  const std::vector<double>* model = nullptr;  // the posed model's points, same frame; may be empty
  double side_axis[2] = {1.0, 0.0};            // unit ground-plane direction the side view runs along
  std::string title;
  bool confident = false;  // title green, else amber
};

constexpr int kAnswerPanelPx = 480;                 // pixels along the longest extent of either view
constexpr double kAnswerMinMetresPerPixel = 0.005;  // small objects are not blown up further

// Writes the PNG; false with *error when there is no query point or the write fails.
bool write_answer_picture(const std::string& path, const AnswerPicture& p, std::string* error);

}  // namespace spinhash::host
