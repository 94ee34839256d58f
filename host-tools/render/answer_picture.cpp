#include "render/answer_picture.hpp"

#include <algorithm>
#include <cmath>

#include "render/canvas.hpp"

namespace spinhash::host {
namespace {

constexpr int kMarginPx = 24, kTitlePx = 44, kGapPx = 40, kFooterPx = 30;
constexpr int kTitleScale = 3, kLabelScale = 2;
constexpr int kQueryDotRadius = 1, kModelDotRadius = 2;  // the sparser model points drawn larger, on top
constexpr Rgb kBackground{18, 18, 24}, kText{240, 240, 240}, kQuery{150, 170, 200}, kModel{255, 140, 0};
constexpr Rgb kConfident{60, 220, 90}, kUnsure{255, 160, 40};

// A view: each point mapped to (horizontal, vertical) metres about the centre.
struct View {
  std::vector<double> h, v;
  double lo_h = 0, hi_h = 0, lo_v = 0, hi_v = 0;
};

void add_points(const std::vector<double>& xyz, const double centre[3], const double axis[2], bool side,
                View* view) {
  for (size_t i = 0; i + 2 < xyz.size(); i += 3) {
    const double x = xyz[i] - centre[0], y = xyz[i + 1] - centre[1], z = xyz[i + 2] - centre[2];
    view->h.push_back(side ? x * axis[0] + y * axis[1] : x);
    view->v.push_back(side ? z : y);
  }
}

void bounds(View* view) {
  view->lo_h = *std::min_element(view->h.begin(), view->h.end());
  view->hi_h = *std::max_element(view->h.begin(), view->h.end());
  view->lo_v = *std::min_element(view->v.begin(), view->v.end());
  view->hi_v = *std::max_element(view->v.begin(), view->v.end());
}

// Draws the view's points [from, to) with its top-left pixel at (x0, y0).
void draw(Canvas* c, const View& view, size_t from, size_t to, int x0, int y0, double mpp, int radius,
          Rgb colour) {
  for (size_t i = from; i < to; ++i) {
    const int px = x0 + static_cast<int>((view.h[i] - view.lo_h) / mpp);
    const int py = y0 + static_cast<int>((view.hi_v - view.v[i]) / mpp);
    c->dot(px, py, radius, colour);
  }
}

int span_px(double lo, double hi, double mpp) { return static_cast<int>((hi - lo) / mpp) + 1; }

}  // namespace

bool write_answer_picture(const std::string& path, const AnswerPicture& p, std::string* error) {
  static const std::vector<double> kNone;
  const std::vector<double>& query = p.query ? *p.query : kNone;
  const std::vector<double>& model = p.model ? *p.model : kNone;
  if (query.size() < 3) {
    if (error) *error = path + ": no query points to draw";
    return false;
  }
  const double centre[3] = {query[0], query[1], query[2]};  // keeps georeferenced values small
  View top, side;
  for (View* v : {&top, &side}) {
    add_points(query, centre, p.side_axis, v == &side, v);
    add_points(model, centre, p.side_axis, v == &side, v);
    bounds(v);
  }
  const double extent =
      std::max({top.hi_h - top.lo_h, top.hi_v - top.lo_v, side.hi_h - side.lo_h, side.hi_v - side.lo_v});
  const double mpp = std::max(kAnswerMinMetresPerPixel, extent / kAnswerPanelPx);
  const int top_w = span_px(top.lo_h, top.hi_h, mpp), top_h = span_px(top.lo_v, top.hi_v, mpp);
  const int side_w = span_px(side.lo_h, side.hi_h, mpp), side_h = span_px(side.lo_v, side.hi_v, mpp);
  const int panels_w = top_w + kGapPx + side_w;
  const int width = 2 * kMarginPx + std::max(panels_w, Canvas::text_width(p.title, kTitleScale));
  const int height = kTitlePx + 2 * kLabelScale * 5 + std::max(top_h, side_h) + kFooterPx + kMarginPx;
  Canvas c(static_cast<uint32_t>(width), static_cast<uint32_t>(height), kBackground);
  c.text(kMarginPx, kMarginPx / 2, p.title, kTitleScale, p.confident ? kConfident : kUnsure);
  const int y0 = kTitlePx + 2 * kLabelScale * 5, side_x0 = kMarginPx + top_w + kGapPx;
  c.text(kMarginPx, kTitlePx, "TOP DOWN (NORTH UP)", kLabelScale, kText);
  c.text(side_x0, kTitlePx, "SIDE ON (Z UP)", kLabelScale, kText);
  const size_t nq = query.size() / 3, n = nq + model.size() / 3;
  draw(&c, top, 0, nq, kMarginPx, y0, mpp, kQueryDotRadius, kQuery);  // the query under the model
  draw(&c, side, 0, nq, side_x0, y0, mpp, kQueryDotRadius, kQuery);
  draw(&c, top, nq, n, kMarginPx, y0, mpp, kModelDotRadius, kModel);
  draw(&c, side, nq, n, side_x0, y0, mpp, kModelDotRadius, kModel);
  const int bar = static_cast<int>(1.0 / mpp), bar_y = height - kMarginPx;  // 1 m scale bar
  for (int t = 0; t < 3; ++t) c.line(kMarginPx, bar_y + t, kMarginPx + bar, bar_y + t, kText);
  c.text(kMarginPx + bar + 6, bar_y - 2, "1 M", kLabelScale, kText);
  const int key_x = kMarginPx + bar + 60;
  c.text(key_x, bar_y - 2, "QUERY", kLabelScale, kQuery);
  c.text(key_x + Canvas::text_width("QUERY  ", kLabelScale), bar_y - 2, "MODEL", kLabelScale, kModel);
  return c.write_png(path, error);
}

}  // namespace spinhash::host
