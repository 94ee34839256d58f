// host::parse_cloud (PLY ascii/binary and x y z text) on arbitrary bytes: it
// must return true with whole triples or false with a message, never crash,
// hang or allocate beyond what the bytes can justify.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"
#include "fuzz_require.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::vector<double> xyz;
  std::string error;
  if (spinhash::host::parse_cloud(bytes, &xyz, &error)) {
    spinhash::fuzz::require(xyz.size() % 3 == 0, "points are not whole triples");
  } else {
    spinhash::fuzz::require(!error.empty(), "failure without a message");
  }
  return 0;
}
