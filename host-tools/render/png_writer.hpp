// PNG files from an RGB image: the scanlines (filter none) deflated by zlib
// (Debian's zlib1g), which keeps pictures of flat colours small (an empty
// survey's overview is a few kilobytes).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

constexpr uint32_t kMaxPngSide = 16384;  // pixels: bounds a picture's memory

// PNG bytes of a width x height RGB8 image (row-major, 3 bytes per pixel);
// empty when a side is 0 or above kMaxPngSide or rgb has the wrong size.
std::string png_bytes(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgb);

// The same, written atomically; false with *error.
bool write_png(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgb,
               std::string* error);

// CRC-32 (ISO-HDLC, as PNG chunks use; zlib's), exposed for tests.
uint32_t png_crc32(const uint8_t* data, size_t n, uint32_t crc = 0);

}  // namespace spinhash::host
