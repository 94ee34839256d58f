#include "render/canvas.hpp"

#include <cstdlib>

#include "render/font3x5.hpp"
#include "render/png_writer.hpp"

namespace spinhash::host {

Canvas::Canvas(uint32_t width, uint32_t height, Rgb background)
    : width_(width), height_(height), background_(background) {
  rgb_.resize(static_cast<size_t>(width) * height * 3u);
  for (size_t i = 0; i < rgb_.size(); i += 3) {
    rgb_[i] = background.r;
    rgb_[i + 1] = background.g;
    rgb_[i + 2] = background.b;
  }
}

Rgb Canvas::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= static_cast<int>(width_) || y >= static_cast<int>(height_)) return background_;
  const size_t i = (static_cast<size_t>(y) * width_ + static_cast<size_t>(x)) * 3u;
  return Rgb{rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

void Canvas::put(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= static_cast<int>(width_) || y >= static_cast<int>(height_)) return;
  const size_t i = (static_cast<size_t>(y) * width_ + static_cast<size_t>(x)) * 3u;
  rgb_[i] = c.r;
  rgb_[i + 1] = c.g;
  rgb_[i + 2] = c.b;
}

void Canvas::dot(int x, int y, int radius, Rgb c) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) put(x + dx, y + dy, c);
}

void Canvas::line(int x0, int y0, int x1, int y1, Rgb c) {
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  for (int steps = 0; steps <= dx - dy; ++steps) {  // bounded: one pixel per step
    put(x0, y0, c);
    if (x0 == x1 && y0 == y1) return;
    const int e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
}

void Canvas::text(int x, int y, const std::string& s, int scale, Rgb c) {
  for (size_t k = 0; k < s.size(); ++k) {
    const uint8_t* rows = glyph_rows(s[k]);
    if (rows == nullptr) rows = glyph_rows('?');
    const int left = x + static_cast<int>(k) * kGlyphAdvance * scale;
    for (int r = 0; r < kGlyphHeight; ++r)
      for (int col = 0; col < kGlyphWidth; ++col)
        if (rows[r] & (1u << (kGlyphWidth - 1 - col)))
          for (int py = 0; py < scale; ++py)
            for (int px = 0; px < scale; ++px) put(left + col * scale + px, y + r * scale + py, c);
  }
}

int Canvas::text_width(const std::string& s, int scale) {
  return s.empty() ? 0 : (static_cast<int>(s.size()) * kGlyphAdvance - 1) * scale;
}

bool Canvas::write_png(const std::string& path, std::string* error) const {
  return host::write_png(path, width_, height_, rgb_, error);
}

}  // namespace spinhash::host
