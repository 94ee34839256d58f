#include "render/png_writer.hpp"

#include "blob/file_io.hpp"

namespace spinhash::host {
namespace {

constexpr uint32_t kStoredBlockMax = 65535;  // bytes in one stored deflate block
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

// zlib stream of stored blocks over `raw`.
std::string zlib_stored(const std::string& raw) {
  std::string z = "\x78\x01";  // deflate, 32 KiB window, no dictionary, check bits
  size_t at = 0;
  do {
    const size_t n = raw.size() - at < kStoredBlockMax ? raw.size() - at : kStoredBlockMax;
    const bool last = at + n == raw.size();
    z.push_back(static_cast<char>(last ? 1 : 0));  // BFINAL, BTYPE = 00 (stored)
    z.push_back(static_cast<char>(n & 0xFFu));
    z.push_back(static_cast<char>((n >> 8) & 0xFFu));
    z.push_back(static_cast<char>(~n & 0xFFu));
    z.push_back(static_cast<char>((~n >> 8) & 0xFFu));
    z.append(raw, at, n);
    at += n;
  } while (at < raw.size());
  put_be32(&z, adler32(reinterpret_cast<const uint8_t*>(raw.data()), raw.size()));
  return z;
}

}  // namespace

uint32_t png_crc32(const uint8_t* data, size_t n, uint32_t crc) {
  crc = ~crc;
  for (size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

uint32_t adler32(const uint8_t* data, size_t n) {
  constexpr uint32_t kMod = 65521;
  uint32_t a = 1, b = 0;
  for (size_t i = 0; i < n; ++i) {
    a = (a + data[i]) % kMod;
    b = (b + a) % kMod;
  }
  return (b << 16) | a;
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
  chunk(&png, "IDAT", zlib_stored(raw));
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
