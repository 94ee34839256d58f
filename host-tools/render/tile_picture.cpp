#include "render/tile_picture.hpp"

#include <algorithm>
#include <cmath>

#include "render/canvas.hpp"
#include "util/angles.hpp"

namespace spinhash::host {
namespace {

constexpr int kMarginPx = 30;   // around the tile, room for labels and the title
constexpr int kLabelScale = 2;  // font pixels per glyph pixel
constexpr Rgb kBackground{18, 18, 24}, kTextColour{240, 240, 240}, kLabelBackdrop{0, 0, 0};

Rgb style_colour(BoxStyle s) {
  switch (s) {
    case BoxStyle::kConfident: return {60, 220, 90};
    case BoxStyle::kUnsure: return {255, 160, 40};
    default: return {80, 150, 255};
  }
}

// Low ground dark brown to high grey.
Rgb height_colour(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return Rgb{static_cast<uint8_t>(90 + 110 * t), static_cast<uint8_t>(70 + 120 * t),
             static_cast<uint8_t>(50 + 140 * t)};
}

struct Frame {
  double x0 = 0, y1 = 0, mpp = kPictureMinMetresPerPixel;
  int px(double x) const { return kMarginPx + static_cast<int>(std::floor((x - x0) / mpp)); }
  int py(double y) const { return kMarginPx + static_cast<int>(std::floor((y1 - y) / mpp)); }
};

bool inside(const PictureBox& b, double x, double y) {
  const double h = b.heading_deg * kDegToRad, dx = x - b.center[0], dy = y - b.center[1];
  const double u = dx * std::cos(h) + dy * std::sin(h), v = -dx * std::sin(h) + dy * std::cos(h);
  return std::fabs(u) <= 0.5 * b.length && std::fabs(v) <= 0.5 * b.width;
}

void outline(Canvas* c, const Frame& f, const PictureBox& b) {
  const double h = b.heading_deg * kDegToRad;
  const double ux = std::cos(h), uy = std::sin(h);
  double cx[4], cy[4];
  const double su[4] = {0.5, 0.5, -0.5, -0.5}, sv[4] = {0.5, -0.5, -0.5, 0.5};
  for (int k = 0; k < 4; ++k) {
    cx[k] = b.center[0] + su[k] * b.length * ux - sv[k] * b.width * uy;
    cy[k] = b.center[1] + su[k] * b.length * uy + sv[k] * b.width * ux;
  }
  const Rgb col = style_colour(b.style);
  for (int k = 0; k < 4; ++k)
    for (int w = 0; w < 2; ++w)  // 2 px wide
      c->line(f.px(cx[k]) + w, f.py(cy[k]), f.px(cx[(k + 1) % 4]) + w, f.py(cy[(k + 1) % 4]), col);
  int top = f.py(cy[0]), left = f.px(cx[0]);
  for (int k = 1; k < 4; ++k) top = std::min(top, f.py(cy[k])), left = std::min(left, f.px(cx[k]));
  const int w = Canvas::text_width(b.label, kLabelScale), h5 = 5 * kLabelScale;
  for (int y = top - h5 - 4; y < top - 1; ++y)
    for (int x = left - 1; x < left + w + 1; ++x) c->put(x, y, kLabelBackdrop);
  c->text(left, top - h5 - 3, b.label, kLabelScale, col);
}

}  // namespace

bool write_tile_picture(const std::string& path, const std::vector<double>& xyz,
                        const std::vector<PictureBox>& boxes, const std::string& title, std::string* error) {
  const size_t n = xyz.size() / 3;
  if (n == 0) {
    if (error) *error = path + ": no points to draw";
    return false;
  }
  double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {xyz[0], xyz[1], xyz[2]};
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], xyz[3 * i + a]), hi[a] = std::max(hi[a], xyz[3 * i + a]);
  Frame f;
  f.x0 = lo[0];
  f.y1 = hi[1];
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  f.mpp = std::max(kPictureMinMetresPerPixel, extent / kPictureSide);
  const int dot = static_cast<int>(0.5 * kPicturePointSpacing / f.mpp);  // dots meet at the usual spacing
  const uint32_t w = static_cast<uint32_t>((hi[0] - lo[0]) / f.mpp) + 1 + 2 * kMarginPx;
  const uint32_t h = static_cast<uint32_t>((hi[1] - lo[1]) / f.mpp) + 1 + 2 * kMarginPx;
  Canvas c(w, h, kBackground);
  const double zspan = hi[2] - lo[2] > 1e-6 ? hi[2] - lo[2] : 1.0;
  for (size_t i = 0; i < n; ++i) {
    const double x = xyz[3 * i], y = xyz[3 * i + 1];
    Rgb col = height_colour((xyz[3 * i + 2] - lo[2]) / zspan);
    for (const PictureBox& b : boxes)
      if (inside(b, x, y)) col = style_colour(b.style);
    c.dot(f.px(x), f.py(y), dot, col);
  }
  for (const PictureBox& b : boxes) outline(&c, f, b);
  c.text(6, 6, title, kLabelScale, kTextColour);
  const int bar = static_cast<int>(10.0 / f.mpp);  // 10 m scale bar, bottom left
  for (int t = 0; t < 3; ++t)
    c.line(kMarginPx, static_cast<int>(h) - 14 + t, kMarginPx + bar, static_cast<int>(h) - 14 + t,
           kTextColour);
  c.text(kMarginPx + bar + 6, static_cast<int>(h) - 15, "10 M", kLabelScale, kTextColour);
  return c.write_png(path, error);
}

}  // namespace spinhash::host
