// Inputs the fuzzers (fuzz/) once failed on, kept as plain tests so the fix
// stays fixed in every build, with or without the sanitizers.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"
#include "cloud_test_support.hpp"

namespace {

// An ASCII PLY with no vertices and one element holding a list of `count` items.
std::string ply_with_list_count(const std::string& count) {
  return "ply\nformat ascii 1.0\nelement vertex 0\nproperty double x\nproperty double y\nproperty double z\n"
         "element e 1\nproperty list uchar int v\nend_header\n" +
         count + " 1 2\n";
}

}  // namespace

TEST_CASE("fuzz_cloud_reader: an ASCII list length beyond uint64 is refused, not cast") {
  // Found by fuzz_cloud_reader: 3.2e78 was cast to uint64_t before any range
  // check (undefined behaviour, reported by UBSan's float-cast-overflow).
  for (const char* count :
       {"3.2222222222222222e78", "1e19", "18446744073709551616", "4294967296", "-1", "2.5", "nan", "inf"}) {
    CAPTURE(count);
    std::vector<double> xyz;
    std::string error;
    CHECK_FALSE(spinhash::host::test::try_read_cloud_bytes(ply_with_list_count(count), &xyz, &error));
    CHECK(error.find("list length") != std::string::npos);
  }
  std::vector<double> xyz;
  std::string error;
  CHECK(spinhash::host::test::try_read_cloud_bytes(ply_with_list_count("2"), &xyz, &error));
  CHECK(xyz.empty());
}
