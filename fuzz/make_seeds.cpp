// Writes the seed corpus of the three fuzzers: a few valid inputs and a few
// broken ones per target, small enough for fast runs. The files in
// fuzz/corpus/ were made by `fuzz_make_seeds fuzz/corpus`; re-run it after a
// blob format change (the valid seeds must stay valid).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "blob/blob_writer.hpp"
#include "db/tiny_blob.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;
namespace fs = std::filesystem;

namespace {

constexpr uint32_t kSeedModels = 2;
constexpr uint32_t kSeedFeaturesPerModel = 6;
constexpr uint64_t kSeedSeed = 5;
constexpr size_t kTruncatedBlobBytes = 300;
constexpr float kViewSpacing = 0.25f;  // m: a sparse toy view keeps the seed small

bool write(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out);
}

template <typename T>
void append(std::string* s, T v) {
  s->append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::string blob_bytes(host::ByteOrder order) {
  std::vector<uint8_t> bytes;
  std::string error;
  if (!host::serialize_blob(host::make_tiny_blob_content(kSeedModels, kSeedFeaturesPerModel, kSeedSeed),
                            order, &bytes, &error)) {
    std::fprintf(stderr, "make_seeds: %s\n", error.c_str());
    std::exit(1);
  }
  return std::string(bytes.begin(), bytes.end());
}

bool database_seeds(const fs::path& dir) {
  const std::string native = blob_bytes(host::ByteOrder::kNative);
  const std::string other = blob_bytes(host::opposite_byte_order(host::ByteOrder::kNative));
  // First byte: fuzzer flags (bit 0: re-seal checksums), see fuzz_database_open.cpp.
  return write(dir / "valid", std::string(1, '\0') + native) &&
         write(dir / "valid-resealed", std::string(1, '\1') + native) &&
         write(dir / "truncated", std::string(1, '\0') + native.substr(0, kTruncatedBlobBytes)) &&
         write(dir / "other-byte-order", std::string(1, '\0') + other) &&
         write(dir / "header-only", std::string(1, '\1') + native.substr(0, sizeof(blob::Header)));
}

bool recognize_seeds(const fs::path& dir) {
  // Control byte: bits 0-1 encoding, 2-3 mode, 4 refuse; see fuzz_recognize.cpp.
  const double origin[3] = {0.0, 0.0, 0.0};
  const std::vector<double> view =
      test::toy_query(test::toy_vehicle_points(2, kViewSpacing), 0.3, origin, 0.02, 1);
  std::string cm(1, '\x01'), utm(1, '\x0a'), raw(1, '\x00'), dbl(1, '\x07');
  for (double v : view) {
    append(&cm, static_cast<int16_t>(v * 100.0));
    append(&utm, static_cast<int16_t>(v * 100.0));
  }
  const float hostile[] = {1.0f, 2.0f, 3.0f, NAN, 0.0f, 0.0f, INFINITY, 1.0f, 1.0f, 3.0e38f, -3.0e38f, 0.0f};
  for (float v : hostile) append(&raw, v);
  for (double v : {0.0, 0.0, 0.0, 1e300, -1e300, 0.0, 4.0e6, 4.0e6, 4.0e6}) append(&dbl, v);
  return write(dir / "toy-view-cm", cm) && write(dir / "toy-view-utm-sran", utm) &&
         write(dir / "hostile-float", raw) && write(dir / "hostile-double-sind", dbl) &&
         write(dir / "empty", std::string(1, '\x02'));
}

bool cloud_seeds(const fs::path& dir) {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  std::string le =
      "ply\nformat binary_little_endian 1.0\ncomment seed\nelement vertex 2\nproperty double x\n"
      "property double y\nproperty double z\nproperty uchar intensity\nelement face 0\n"
      "property list uchar int vertex_indices\nend_header\n";
  std::string be = "ply\nformat binary_big_endian 1.0\nelement vertex 1\n" + xyz + "end_header\n";
  for (double v : {1.0, 2.0, 3.0}) append(&le, v);
  le.push_back('\x07');
  for (double v : {431000.5, 4020000.25, 87.0}) append(&le, v);
  le.push_back('\x08');
  be += std::string("\x3f\x80\x00\x00\x40\x00\x00\x00\x40\x40\x00\x00", 12);
  return write(dir / "ascii.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                                      "end_header\n1 2 3\n4 5 6\nnan inf -7\n") &&
         write(dir / "binary-le.ply", le) && write(dir / "binary-be.ply", be) &&
         write(dir / "text.xyz", "1 2 3\n4.5 -6e2 7\n# comment\n8,9,10\n") &&
         write(dir / "truncated.ply", le.substr(0, le.size() - 5)) &&
         write(dir / "bad-count.ply",
               "ply\nformat ascii 1.0\nelement vertex 9\n" + xyz + "end_header\n1 2 3\n") &&
         write(dir / "bad-type.ply",
               "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n1\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_make_seeds OUTPUT_DIR\n");
    return 1;
  }
  const fs::path root = argv[1];
  for (const char* t : {"database_open", "recognize", "cloud_reader"}) fs::create_directories(root / t);
  const bool ok = database_seeds(root / "database_open") && recognize_seeds(root / "recognize") &&
                  cloud_seeds(root / "cloud_reader");
  if (!ok) std::fprintf(stderr, "make_seeds: cannot write under %s\n", argv[1]);
  return ok ? 0 : 1;
}
