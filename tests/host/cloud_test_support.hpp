// The reading door's throwing helpers (cloud/cloud_reader.hpp) as true /
// false with the message, for tests that check what a reader refuses and
// how it says so.
#pragma once
#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"

namespace spinhash::host::test {

inline bool try_read_cloud(const std::string& path, std::vector<double>* xyz, std::string* error) {
  try {
    *xyz = read_cloud(path);
    return true;
  } catch (const CloudError& e) {
    xyz->clear();
    *error = e.what();
    return false;
  }
}

inline bool try_read_cloud_bytes(const std::string& bytes, std::vector<double>* xyz, std::string* error) {
  try {
    *xyz = read_cloud_bytes(bytes);
    return true;
  } catch (const CloudError& e) {
    xyz->clear();
    *error = e.what();
    return false;
  }
}

}  // namespace spinhash::host::test
