// host::read_cloud_bytes (the reading door over bytes: LAS/LAZ, PLY ascii or
// binary, x y z text) on arbitrary bytes: it must return whole triples or
// throw a CloudError with a message, never crash, hang or allocate beyond
// what the bytes can justify.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"
#include "fuzz_require.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const std::vector<double> xyz = spinhash::host::read_cloud_bytes(bytes);
    spinhash::fuzz::require(xyz.size() % 3 == 0, "points are not whole triples");
  } catch (const spinhash::host::CloudError& e) {
    spinhash::fuzz::require(e.what()[0] != '\0', "failure without a message");
  }
  return 0;
}
