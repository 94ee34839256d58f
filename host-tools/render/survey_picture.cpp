#include "render/survey_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/canvas.hpp"
#include "render/font3x5.hpp"
#include "util/angles.hpp"

namespace spinhash::host {
namespace {

constexpr int kMarginPx = 20, kTitleBandPx = 28, kLegendBandPx = 34;
constexpr int kLabelScale = 1, kTitleScale = 2;  // font pixels per glyph pixel
constexpr int kLabelGapPx = 2;                   // between a label and its vehicle
constexpr int kTileLabelInsetPx = 3;             // a tile's name from its edges, and between stacked names
constexpr int kMinPictureWidthPx = 640;          // room for the legend
constexpr double kScaleBarFraction = 0.2;        // of the picture's width, rounded down to 1-2-5 m
constexpr Rgb kBackground{250, 250, 247}, kText{30, 30, 30}, kTileLine{170, 170, 170}, kClutter{60, 120, 230};
constexpr Rgb kConfidentFill{40, 170, 70}, kConfidentEdge{10, 80, 30};
constexpr Rgb kUnsureFill{250, 160, 40}, kUnsureEdge{150, 80, 0};

struct Frame {
  double x0 = 0, y1 = 0, ppm = 1;  // pixels per metre
  int px(double x) const { return kMarginPx + static_cast<int>(std::floor((x - x0) * ppm)); }
  int py(double y) const { return kTitleBandPx + static_cast<int>(std::floor((y1 - y) * ppm)); }
};

struct PixelRect {
  int x0, y0, x1, y1;  // inclusive
  bool overlaps(const PixelRect& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

Frame frame_of(const std::vector<SurveyPictureTile>& tiles, int* w, int* h) {
  double lo[2] = {tiles[0].min[0], tiles[0].min[1]}, hi[2] = {tiles[0].max[0], tiles[0].max[1]};
  for (const SurveyPictureTile& t : tiles)
    for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], t.min[a]), hi[a] = std::max(hi[a], t.max[a]);
  Frame f;
  f.x0 = lo[0], f.y1 = hi[1];
  f.ppm =
      std::min(kSurveyMaxPixelsPerMetre, kSurveyPictureSide / std::max({hi[0] - lo[0], hi[1] - lo[1], 1.0}));
  *w = std::max(static_cast<int>((hi[0] - lo[0]) * f.ppm) + 2 * kMarginPx + 1, kMinPictureWidthPx);
  *h = static_cast<int>((hi[1] - lo[1]) * f.ppm) + kTitleBandPx + kLegendBandPx + 1;
  return f;
}

// Each tile's name inside its top-left corner, or lower down its left edge
// (a line at a time), or inside its other corners, wherever it meets no
// name placed before: tiles that overlap, or share a corner, keep legible
// names. Empty (x1 < x0) when no place is free.
std::vector<PixelRect> tile_label_places(const Frame& f, const std::vector<SurveyPictureTile>& tiles) {
  std::vector<PixelRect> placed;
  const int h = kGlyphHeight * kLabelScale;
  for (const SurveyPictureTile& t : tiles) {
    const int w = Canvas::text_width(t.name, kLabelScale);
    const PixelRect tile{f.px(t.min[0]), f.py(t.max[1]), f.px(t.max[0]), f.py(t.min[1])};
    std::vector<PixelRect> options;
    for (int y = tile.y0 + kTileLabelInsetPx; y + h <= tile.y1 - kTileLabelInsetPx;
         y += h + kTileLabelInsetPx)
      options.push_back({tile.x0 + kTileLabelInsetPx, y, tile.x0 + kTileLabelInsetPx + w - 1, y + h - 1});
    options.push_back({tile.x1 - kTileLabelInsetPx - w + 1, tile.y0 + kTileLabelInsetPx,
                       tile.x1 - kTileLabelInsetPx, tile.y0 + kTileLabelInsetPx + h - 1});
    options.push_back({tile.x1 - kTileLabelInsetPx - w + 1, tile.y1 - kTileLabelInsetPx - h + 1,
                       tile.x1 - kTileLabelInsetPx, tile.y1 - kTileLabelInsetPx});
    PixelRect chosen{0, 0, -1, -1};
    for (const PixelRect& o : options)
      if (std::none_of(placed.begin(), placed.end(),
                       [&](const PixelRect& p) { return p.x1 >= p.x0 && p.overlaps(o); })) {
        chosen = o;
        break;
      }
    placed.push_back(chosen);
  }
  return placed;
}

using Quad = std::array<std::array<int, 2>, 4>;

Quad corners(const Frame& f, const PictureBox& b) {
  const double h = b.heading_deg * kDegToRad, ux = std::cos(h), uy = std::sin(h);
  const double su[4] = {0.5, 0.5, -0.5, -0.5}, sv[4] = {0.5, -0.5, -0.5, 0.5};
  Quad q;
  for (int k = 0; k < 4; ++k) {
    q[k][0] = f.px(b.center[0] + su[k] * b.length * ux - sv[k] * b.width * uy);
    q[k][1] = f.py(b.center[1] + su[k] * b.length * uy + sv[k] * b.width * ux);
  }
  return q;
}

PixelRect bounds(const Quad& q) {
  PixelRect r{q[0][0], q[0][1], q[0][0], q[0][1]};
  for (const auto& p : q)
    r.x0 = std::min(r.x0, p[0]), r.y0 = std::min(r.y0, p[1]), r.x1 = std::max(r.x1, p[0]),
    r.y1 = std::max(r.y1, p[1]);
  return r;
}

void outline(Canvas* c, const Quad& q, Rgb col) {
  for (int k = 0; k < 4; ++k) c->line(q[k][0], q[k][1], q[(k + 1) % 4][0], q[(k + 1) % 4][1], col);
}

// A convex quadrilateral: pixels on the inner side of all four edges.
void fill(Canvas* c, const Quad& q, Rgb col) {
  const PixelRect r = bounds(q);
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      int pos = 0, neg = 0;
      for (int k = 0; k < 4; ++k) {
        const auto &a = q[k], &b = q[(k + 1) % 4];
        const long cross =
            static_cast<long>(b[0] - a[0]) * (y - a[1]) - static_cast<long>(b[1] - a[1]) * (x - a[0]);
        pos += cross > 0, neg += cross < 0;
      }
      if (pos == 0 || neg == 0) c->put(x, y, col);
    }
}

// The first of right, left, above, below the vehicle where the label lies
// within the picture and meets no placed label and no vehicle; false when
// none is free.
bool place_label(const PixelRect& v, int w, int h, const PixelRect& picture,
                 const std::vector<PixelRect>& taken, PixelRect* out) {
  const int cy = (v.y0 + v.y1) / 2 - h / 2, cx = (v.x0 + v.x1) / 2 - w / 2;
  const PixelRect options[4] = {{v.x1 + kLabelGapPx, cy, v.x1 + kLabelGapPx + w, cy + h},
                                {v.x0 - kLabelGapPx - w, cy, v.x0 - kLabelGapPx, cy + h},
                                {cx, v.y0 - kLabelGapPx - h, cx + w, v.y0 - kLabelGapPx},
                                {cx, v.y1 + kLabelGapPx, cx + w, v.y1 + kLabelGapPx + h}};
  for (const PixelRect& o : options)
    if (o.x0 >= picture.x0 && o.y0 >= picture.y0 && o.x1 <= picture.x1 && o.y1 <= picture.y1 &&
        std::none_of(taken.begin(), taken.end(), [&](const PixelRect& t) { return t.overlaps(o); })) {
      *out = o;
      return true;
    }
  return false;
}

void legend(Canvas* c, int y) {
  int x = kMarginPx;
  const auto item = [&](Rgb fill_col, Rgb edge, bool filled, const std::string& text) {
    const Quad q{{{x, y}, {x + 14, y}, {x + 14, y + 8}, {x, y + 8}}};
    if (filled) fill(c, q, fill_col);
    outline(c, q, edge);
    c->text(x + 20, y + 2, text, kLabelScale, kText);
    x += 28 + Canvas::text_width(text, kLabelScale);
  };
  item(kConfidentFill, kConfidentEdge, true, "vehicle, confident: model");
  item(kUnsureFill, kUnsureEdge, true, "vehicle, not confident: model ?");
  item(kClutter, kClutter, false, "not a vehicle");
  item(kTileLine, kTileLine, false, "tile");
}

void scale_bar(Canvas* c, const Frame& f, int width_px, int y) {
  double metres = width_px * kScaleBarFraction / f.ppm;
  const double p10 = std::pow(10.0, std::floor(std::log10(metres)));
  metres = metres >= 5 * p10 ? 5 * p10 : metres >= 2 * p10 ? 2 * p10 : p10;
  const int len = static_cast<int>(metres * f.ppm), x1 = width_px - kMarginPx, x0 = x1 - len;
  for (int t = 0; t < 2; ++t) c->line(x0, y + t, x1, y + t, kText);
  char label[32];
  std::snprintf(label, sizeof label, "%g M", metres);
  c->text(x0 - Canvas::text_width(label, kLabelScale) - 4, y - 2, label, kLabelScale, kText);
}

}  // namespace

std::vector<std::array<int, 4>> survey_tile_labels(const std::vector<SurveyPictureTile>& tiles) {
  std::vector<std::array<int, 4>> out;
  if (tiles.empty()) return out;
  int w = 0, h = 0;
  for (const PixelRect& r : tile_label_places(frame_of(tiles, &w, &h), tiles))
    out.push_back({r.x0, r.y0, r.x1, r.y1});
  return out;
}

bool write_survey_picture(const std::string& path, const std::vector<SurveyPictureTile>& tiles,
                          const std::vector<PictureBox>& boxes, const std::string& title,
                          std::string* error) {
  if (tiles.empty()) {
    *error = path + ": no tile to draw";
    return false;
  }
  int w = 0, h = 0;
  const Frame f = frame_of(tiles, &w, &h);
  Canvas c(static_cast<uint32_t>(w), static_cast<uint32_t>(h), kBackground);
  const std::vector<PixelRect> names = tile_label_places(f, tiles);
  for (size_t i = 0; i < tiles.size(); ++i) {
    const SurveyPictureTile& t = tiles[i];
    const Quad q{{{f.px(t.min[0]), f.py(t.max[1])},
                  {f.px(t.max[0]), f.py(t.max[1])},
                  {f.px(t.max[0]), f.py(t.min[1])},
                  {f.px(t.min[0]), f.py(t.min[1])}}};
    outline(&c, q, kTileLine);
    if (names[i].x1 >= names[i].x0) c.text(names[i].x0, names[i].y0, t.name, kLabelScale, kTileLine);
  }
  for (const PictureBox& b : boxes)  // clutter first, as outlines, so that vehicles lie on top
    if (b.style == BoxStyle::kNotVehicle) outline(&c, corners(f, b), kClutter);
  const PixelRect inside{0, kTitleBandPx, static_cast<int>(c.width()) - 1, h - kLegendBandPx};
  std::vector<PixelRect> taken;
  for (const PictureBox& b : boxes)
    if (b.style != BoxStyle::kNotVehicle) taken.push_back(bounds(corners(f, b)));
  for (const PictureBox& b : boxes) {
    if (b.style == BoxStyle::kNotVehicle) continue;
    const Quad q = corners(f, b);
    const bool sure = b.style == BoxStyle::kConfident;
    fill(&c, q, sure ? kConfidentFill : kUnsureFill);
    outline(&c, q, sure ? kConfidentEdge : kUnsureEdge);
    PixelRect at;
    if (place_label(bounds(q), Canvas::text_width(b.label, kLabelScale), 5 * kLabelScale, inside, taken,
                    &at)) {
      taken.push_back(at);
      c.text(at.x0, at.y0, b.label, kLabelScale, sure ? kConfidentEdge : kUnsureEdge);
    }
  }
  c.text(kMarginPx, 6, title, kTitleScale, kText);
  legend(&c, h - kLegendBandPx + 12);
  scale_bar(&c, f, static_cast<int>(c.width()), h - kLegendBandPx + 14);
  return c.write_png(path, error);
}

}  // namespace spinhash::host
