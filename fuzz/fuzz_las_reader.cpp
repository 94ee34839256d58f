// host::parse_las on arbitrary bytes: it must return true with whole triples
// and one class per point, or false with a message; never crash, hang, or
// allocate beyond what the bytes can hold. Compressed (LAZ) input is left
// to fuzz_laz_reader, which bounds the points it decodes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cloud/las_reader.hpp"
#include "fuzz_require.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr size_t kFormatAt = 104;
  constexpr uint8_t kCompressedBits = 0xC0;
  if (size > kFormatAt && (data[kFormatAt] & kCompressedBits) != 0) return 0;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  spinhash::host::LasCloud cloud;
  std::string error;
  if (spinhash::host::parse_las(bytes, &cloud, &error)) {
    spinhash::fuzz::require(cloud.xyz.size() == 3 * cloud.classification.size(),
                            "points and classes disagree");
    spinhash::fuzz::require(cloud.header.point_count * cloud.header.record_length <= size,
                            "more points than bytes");
  } else {
    spinhash::fuzz::require(!error.empty(), "failure without a message");
    spinhash::fuzz::require(cloud.xyz.empty(), "a partial cloud after a failure");
  }
  return 0;
}
