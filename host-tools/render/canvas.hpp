// An RGB raster for the pictures the tools write (tiles, overlays): dots,
// lines, oriented boxes and short labels in a 3 x 5 pixel font, clipped to
// the image, then saved as PNG.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
};

class Canvas {
 public:
  Canvas(uint32_t width, uint32_t height, Rgb background);
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  Rgb at(int x, int y) const;  // background outside the image
  void put(int x, int y, Rgb c);
  void dot(int x, int y, int radius, Rgb c);         // filled square of side 2 radius + 1
  void line(int x0, int y0, int x1, int y1, Rgb c);  // Bresenham
  // Text with its top-left corner at (x, y), each font pixel scale x scale;
  // letters are drawn as capitals, characters without a glyph as '?'.
  void text(int x, int y, const std::string& s, int scale, Rgb c);
  static int text_width(const std::string& s, int scale);
  bool write_png(const std::string& path, std::string* error) const;

 private:
  uint32_t width_, height_;
  Rgb background_;
  std::vector<uint8_t> rgb_;
};

}  // namespace spinhash::host
