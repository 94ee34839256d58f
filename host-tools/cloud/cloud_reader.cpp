#include "cloud/cloud_reader.hpp"

namespace spinhash::host {

std::vector<double> read_cloud(const std::string& path) {
  const std::unique_ptr<PointSource> source = open_point_source(path);
  return read_all_points(*source);
}

std::vector<double> read_cloud_bytes(const std::string& bytes, const std::string& name) {
  const std::unique_ptr<PointSource> source = open_point_source_bytes(bytes, name);
  return read_all_points(*source);
}

}  // namespace spinhash::host
