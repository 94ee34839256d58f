#include "support/golden_files.hpp"

#include <doctest/doctest.h>

#include <string>

#include "blob/byte_order.hpp"
#include "blob/file_io.hpp"
#include "golden/golden_expected.hpp"
#include "golden/golden_stream_expected.hpp"

namespace spinhash {
namespace test {
namespace {

host::AlignedBytes read_golden(const char* name) {
  host::AlignedBytes bytes;
  std::string error;
  const std::string path = std::string(SPINHASH_GOLDEN_DIR) + "/" + name;
  CAPTURE(path);
  CAPTURE(error);
  REQUIRE(host::read_file(path, &bytes, &error));
  return bytes;
}

}  // namespace

host::AlignedBytes golden_blob(bool own_byte_order) {
  const bool little = host::native_byte_order() == host::ByteOrder::kLittle;
  host::AlignedBytes blob = read_golden(little == own_byte_order ? "golden_le.shdb" : "golden_be.shdb");
  REQUIRE(blob.size() == golden::kBlobBytes);
  return blob;
}

std::vector<float> golden_query_points() {
  host::AlignedBytes raw = read_golden("golden_queries.i16");
  REQUIRE(raw.size() == static_cast<size_t>(golden::kQueryPoints) * 3u * golden::kBytesPerCoordinate);
  std::vector<float> xyz(raw.size() / golden::kBytesPerCoordinate);
  for (size_t i = 0; i < xyz.size(); ++i)
    xyz[i] = golden::decode_mm(raw.data() + golden::kBytesPerCoordinate * i);
  return xyz;
}

std::vector<double> golden_stream_points() {
  host::AlignedBytes raw = read_golden("golden_stream.i16");
  REQUIRE(raw.size() == static_cast<size_t>(golden::kStreamPoints) * 3u * golden::kStreamBytesPerCoordinate);
  std::vector<double> xyz(raw.size() / golden::kStreamBytesPerCoordinate);
  for (size_t i = 0; i < xyz.size(); ++i)
    xyz[i] =
        golden::decode_stream(raw.data() + golden::kStreamBytesPerCoordinate * i, static_cast<int>(i % 3));
  return xyz;
}

}  // namespace test
}  // namespace spinhash
