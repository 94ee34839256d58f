// The picture writers (host-tools/render): PNG bytes any reader accepts,
// the canvas's font, and a tile picture with its objects outlined.
#include <doctest/doctest.h>
#include <zlib.h>

#include <cmath>
#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"
#include "cloud_test_support.hpp"
#include "geometry_test_support.hpp"
#include "render/canvas.hpp"
#include "render/font3x5.hpp"
#include "render/png_writer.hpp"
#include "render/tile_picture.hpp"

using namespace spinhash::host;

namespace {

uint32_t be32(const std::string& b, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<uint8_t>(b[at + i]);
  return v;
}

// The raw scanlines of a PNG (its one IDAT chunk), inflated by zlib.
std::string inflate_idat(const std::string& png, size_t raw_size) {
  const size_t idat = png.find("IDAT");
  REQUIRE(idat != std::string::npos);
  const uint32_t len = be32(png, idat - 4);
  const std::string z = png.substr(idat + 4, len);
  std::string raw(raw_size, '\0');
  uLongf got = static_cast<uLongf>(raw_size);
  REQUIRE(uncompress(reinterpret_cast<Bytef*>(raw.data()), &got, reinterpret_cast<const Bytef*>(z.data()),
                     static_cast<uLong>(z.size())) == Z_OK);
  CHECK(got == raw_size);
  return raw;
}

}  // namespace

TEST_CASE("CRC-32 gives its reference value") {
  const std::string iend = "IEND";
  CHECK(png_crc32(reinterpret_cast<const uint8_t*>(iend.data()), 4) == 0xAE426082u);
}

TEST_CASE("PNG pixels are compressed: a flat picture is a few kilobytes, not its raw size") {
  const uint32_t w = 1600, h = 1600;  // an overview's size: 7.7 MB of pixels
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3, 240);
  for (uint32_t x = 100; x < 1500; ++x) rgb[(800u * w + x) * 3] = 20;  // a line
  const std::string png = png_bytes(w, h, rgb);
  CHECK(png.size() < 64u * 1024u);
  const std::string raw = inflate_idat(png, static_cast<size_t>(h) * (1 + 3 * w));
  CHECK(static_cast<uint8_t>(raw[800u * (1 + 3 * w) + 1 + 3 * 100]) == 20);
}

TEST_CASE("PNG bytes carry the image: signature, header, checked chunks, the pixels") {
  const uint32_t w = 300, h = 250;
  std::vector<uint8_t> rgb(w * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i * 7 + i / 1000);
  const std::string png = png_bytes(w, h, rgb);
  REQUIRE(png.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
  CHECK(png.substr(12, 4) == "IHDR");
  CHECK(be32(png, 16) == w);
  CHECK(be32(png, 20) == h);
  CHECK(png[24] == 8);  // bit depth
  CHECK(png[25] == 2);  // RGB
  CHECK(be32(png, 29) == png_crc32(reinterpret_cast<const uint8_t*>(png.data()) + 12, 17));
  const std::string raw = inflate_idat(png, h * (1 + 3 * w));
  REQUIRE(raw.size() == h * (1 + 3 * w));
  for (uint32_t y = 0; y < h; y += 37) {
    CHECK(raw[y * (1 + 3 * w)] == 0);  // filter none
    CHECK(raw.compare(y * (1 + 3 * w) + 1, 3 * w,
                      std::string(rgb.begin() + y * 3 * w, rgb.begin() + (y + 1) * 3 * w)) == 0);
  }
  CHECK(png.substr(png.size() - 8, 4) == "IEND");
  CHECK(png_bytes(0, 5, {}).empty());
  CHECK(png_bytes(2, 2, rgb).empty());  // wrong size
}

TEST_CASE("the canvas draws glyphs, lines and clips at the edges") {
  Canvas c(20, 10, Rgb{0, 0, 0});
  const Rgb white{255, 255, 255};
  c.text(1, 1, "a", 1, white);  // drawn as 'A'
  const uint8_t* rows = glyph_rows('A');
  REQUIRE(rows != nullptr);
  for (int r = 0; r < kGlyphHeight; ++r)
    for (int col = 0; col < kGlyphWidth; ++col)
      CHECK((c.at(1 + col, 1 + r).r == 255) == ((rows[r] >> (kGlyphWidth - 1 - col)) & 1u));
  c.line(-5, 8, 30, 8, white);  // clipped, no crash
  CHECK(c.at(0, 8).g == 255);
  CHECK(c.at(19, 8).g == 255);
  CHECK(Canvas::text_width("AB", 2) == 14);
}

TEST_CASE("a tile picture colours and outlines the objects found") {
  test::TempDir dir("render");
  std::vector<double> xyz;
  for (double y = 0.0; y <= 20.0; y += 0.1)
    for (double x = 0.0; x <= 20.0; x += 0.1) xyz.insert(xyz.end(), {500000.0 + x, 4000000.0 + y, 90.0});
  PictureBox car;
  car.center[0] = 500005.0, car.center[1] = 4000005.0, car.length = 4.5, car.width = 1.8,
  car.heading_deg = 30.0;
  car.label = "sedan-03 0.97";
  car.style = BoxStyle::kConfident;
  const std::string path = dir.file("tile.png");
  std::string error;
  REQUIRE_MESSAGE(write_tile_picture(path, xyz, {car}, "TILE 1 OBJECT", &error), error);
  std::string png;
  REQUIRE(spinhash::host::read_file(path, 1u << 30, &png, &error));
  const uint32_t w = be32(png, 16), h = be32(png, 20);
  CHECK(w >= 1050);  // 20 m over 1000 pixels (the loop may stop a step short), and the margins
  CHECK(w <= 1061);
  CHECK(h >= 1050);
  CHECK(h <= 1061);
  const std::string raw = inflate_idat(png, h * (1 + 3 * w));
  auto pixel = [&](int x, int y) {
    const size_t at = static_cast<size_t>(y) * (1 + 3 * w) + 1 + 3 * static_cast<size_t>(x);
    return Rgb{static_cast<uint8_t>(raw[at]), static_cast<uint8_t>(raw[at + 1]),
               static_cast<uint8_t>(raw[at + 2])};
  };
  const Rgb centre = pixel(30 + 250, 30 + 750);  // the car's centre: x 5 m, y 15 m from the top
  CHECK(centre.g > 200);
  CHECK(centre.r < 100);
  const Rgb far = pixel(30 + 750, 30 + 250);  // ground away from the car
  CHECK(far.g < 200);
}
