#include "cloud/coloured_ply.hpp"

#include <cstring>
#include <exception>

#include "blob/file_io.hpp"

namespace spinhash::host {
namespace {

constexpr size_t kAxes = 3, kChannels = 3;

void append_double_le(std::string* out, double value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int shift = 0; shift < 64; shift += 8) out->push_back(static_cast<char>(bits >> shift));
}

}  // namespace

bool write_coloured_ply(const std::string& path, const std::vector<double>& xyz,
                        const std::vector<uint8_t>& rgb, std::string* error) {
  const size_t points = xyz.size() / kAxes;
  if (xyz.size() % kAxes != 0 || rgb.size() != points * kChannels) {
    if (error)
      *error = "cannot write " + path + ": " + std::to_string(points) + " points but " +
               std::to_string(rgb.size() / kChannels) + " colours";
    return false;
  }
  try {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment spinhash overlay\nelement vertex " +
                      std::to_string(points) +
                      "\nproperty double x\nproperty double y\nproperty double z\n"
                      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    out.reserve(out.size() + points * (kAxes * sizeof(double) + kChannels));
    for (size_t i = 0; i < points; ++i) {
      for (size_t a = 0; a < kAxes; ++a) append_double_le(&out, xyz[kAxes * i + a]);
      for (size_t c = 0; c < kChannels; ++c) out.push_back(static_cast<char>(rgb[kChannels * i + c]));
    }
    return write_file_atomically(path, out.data(), out.size(), error);
  } catch (const std::exception& e) {
    if (error) *error = "cannot write " + path + ": " + e.what();
    return false;
  }
}

}  // namespace spinhash::host
