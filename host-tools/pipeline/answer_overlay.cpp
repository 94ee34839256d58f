#include "pipeline/answer_overlay.hpp"

#include <cmath>

#include "cloud/coloured_ply.hpp"
#include "pipeline/recognition_session.hpp"
#include "render/answer_picture.hpp"

namespace spinhash::pipeline {
namespace {

constexpr uint8_t kQueryRgb[3] = {150, 170, 200};  // grey-blue
constexpr uint8_t kModelRgb[3] = {255, 140, 0};    // orange
constexpr double kMinHeadingNorm = 1e-6;           // a model x axis this close to vertical: keep +x

bool finite_point(const double* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

}  // namespace

AnswerOverlay make_answer_overlay(const Database& db, const std::vector<double>& query, const Result& r) {
  AnswerOverlay o;
  for (size_t i = 0; i + 2 < query.size(); i += 3)
    if (finite_point(&query[i])) o.query.insert(o.query.end(), &query[i], &query[i] + 3);
  if (r.ranking_count == 0) return o;
  const RankedModel& best = r.ranking[0];
  o.model_name = model_name(db, best.model);
  o.confident = r.confident;
  if (!best.has_pose) return o;
  const float* R = best.pose.rotation;  // row-major, model -> query
  const double* t = best.pose.translation;
  const blob::ModelRecord& m = db.model(best.model);
  for (uint32_t f = m.first_feature; f < m.first_feature + m.feature_count; ++f) {
    const float* p = db.positions() + 3u * f;
    for (int row = 0; row < 3; ++row) {
      double v = t[row];
      for (int c = 0; c < 3; ++c) v += static_cast<double>(R[3 * row + c]) * static_cast<double>(p[c]);
      o.model.push_back(v);
    }
  }
  const double hx = static_cast<double>(R[0]), hy = static_cast<double>(R[3]), norm = std::hypot(hx, hy);
  if (norm > kMinHeadingNorm) o.heading[0] = hx / norm, o.heading[1] = hy / norm;
  return o;
}

bool write_overlay_ply(const std::string& path, const AnswerOverlay& o, std::string* error) {
  std::vector<double> xyz = o.query;
  xyz.insert(xyz.end(), o.model.begin(), o.model.end());
  std::vector<uint8_t> rgb;
  rgb.reserve(xyz.size());
  for (size_t i = 0; i < xyz.size() / 3; ++i) {
    const uint8_t* c = i < o.query.size() / 3 ? kQueryRgb : kModelRgb;
    rgb.insert(rgb.end(), c, c + 3);
  }
  return host::write_coloured_ply(path, xyz, rgb, error);
}

bool write_overlay_picture(const std::string& path, const std::string& query_name, const AnswerOverlay& o,
                           std::string* error) {
  const std::string answer = o.model_name.empty() ? "NO MODEL"
                             : o.model.empty()    ? o.model_name + " (NO POSE)"
                             : o.confident        ? o.model_name + " CONFIDENT"
                                                  : o.model_name + " NOT CONFIDENT";
  host::AnswerPicture p;
  p.query = &o.query;
  p.model = &o.model;
  p.side_axis[0] = o.heading[0], p.side_axis[1] = o.heading[1];
  p.title = query_name + ": " + answer;
  p.confident = o.confident;
  return host::write_answer_picture(path, p, error);
}

}  // namespace spinhash::pipeline
