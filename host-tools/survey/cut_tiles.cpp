#include "survey/cut_tiles.hpp"

#include <cmath>
#include <filesystem>
#include <map>

#include "cloud/las_writer.hpp"

namespace spinhash::survey {

int cut_into_tiles(const std::vector<double>& xyz, const std::vector<uint8_t>& classification,
                   const CutOptions& o, const std::string& dir, const std::string& prefix,
                   std::string* error) {
  struct Part {
    std::vector<double> xyz;
    std::vector<uint8_t> classification;
  };
  std::map<std::pair<int64_t, int64_t>, Part> parts;
  for (size_t i = 0; i + 2 < xyz.size(); i += 3) {
    if (!(xyz[i] >= o.keep_min[0] && xyz[i] < o.keep_max[0] && xyz[i + 1] >= o.keep_min[1] &&
          xyz[i + 1] < o.keep_max[1]))
      continue;  // outside, or not finite
    Part& p = parts[{static_cast<int64_t>(std::floor(xyz[i] / o.size)),
                     static_cast<int64_t>(std::floor(xyz[i + 1] / o.size))}];
    p.xyz.insert(p.xyz.end(), xyz.begin() + static_cast<long>(i), xyz.begin() + static_cast<long>(i) + 3);
    if (!classification.empty()) p.classification.push_back(classification[i / 3]);
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    *error = "cannot make " + dir + ": " + ec.message();
    return -1;
  }
  for (const auto& kv : parts) {
    const std::string path = dir + "/" + prefix + "_" + std::to_string(kv.first.first) + "_" +
                             std::to_string(kv.first.second) + ".las";
    if (!host::write_las(path, kv.second.xyz, kv.second.classification, error)) return -1;
  }
  return static_cast<int>(parts.size());
}

}  // namespace spinhash::survey
