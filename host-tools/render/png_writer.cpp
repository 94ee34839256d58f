#include "render/png_writer.hpp"

#include <zlib.h>

#include "blob/file_io.hpp"

namespace spinhash::host {
namespace {

// zlib's default: pictures of flat colours and sparse dots shrink some
// hundredfold, at a few tens of ms for the largest.
constexpr int kCompressionLevel = Z_DEFAULT_COMPRESSION;
constexpr uint8_t kColourTypeRgb = 2;
constexpr uint8_t kBitDepth = 8;

void put_be32(std::string* out, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out->push_back(static_cast<char>((v >> s) & 0xFFu));
}

void chunk(std::string* out, const char type[4], const std::string& data) {
  put_be32(out, static_cast<uint32_t>(data.size()));
  std::string body(type, 4);
  body += data;
  out->append(body);
  put_be32(out, png_crc32(reinterpret_cast<const uint8_t*>(body.data()), body.size()));
}

// The zlib stream of `raw` (deflate); empty when zlib fails.
std::string zlib_deflate(const std::string& raw) {
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string z(static_cast<size_t>(size), '\0');
  if (compress2(reinterpret_cast<Bytef*>(z.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                static_cast<uLong>(raw.size()), kCompressionLevel) != Z_OK)
    return "";
  z.resize(static_cast<size_t>(size));
  return z;
}

}  // namespace

uint32_t png_crc32(const uint8_t* data, size_t n, uint32_t crc) {
  return static_cast<uint32_t>(crc32(crc, data, static_cast<uInt>(n)));
}

std::string png_bytes(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgb) {
  if (width == 0 || height == 0 || width > kMaxPngSide || height > kMaxPngSide ||
      rgb.size() != static_cast<size_t>(width) * height * 3u)
    return "";
  std::string raw;
  raw.reserve(static_cast<size_t>(height) * (1u + 3u * width));
  for (uint32_t y = 0; y < height; ++y) {
    raw.push_back('\0');  // filter: none
    raw.append(reinterpret_cast<const char*>(rgb.data()) + static_cast<size_t>(y) * 3u * width, 3u * width);
  }
  std::string png = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  put_be32(&ihdr, width);
  put_be32(&ihdr, height);
  ihdr += {static_cast<char>(kBitDepth), static_cast<char>(kColourTypeRgb), 0, 0, 0};  // no interlace
  chunk(&png, "IHDR", ihdr);
  const std::string idat = zlib_deflate(raw);
  if (idat.empty()) return "";
  chunk(&png, "IDAT", idat);
  chunk(&png, "IEND", "");
  return png;
}

bool write_png(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgb,
               std::string* error) {
  const std::string png = png_bytes(width, height, rgb);
  if (png.empty()) {
    if (error)
      *error = path + ": no picture (empty, larger than " + std::to_string(kMaxPngSide) + " px, or bad size)";
    return false;
  }
  return write_file_atomically(path, png.data(), png.size(), error);
}

}  // namespace spinhash::host
