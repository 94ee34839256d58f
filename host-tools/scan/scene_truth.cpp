// The tile simulator's truth file: one CSV line per object.
#include "scan/scene_simulator.hpp"

#include <cstdio>
#include <fstream>

namespace spinhash::host {
namespace {

std::string number(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

constexpr int kCoordinateDigits = 4;  // 0.1 mm, georeferenced
constexpr int kPoseDigits = 9;

}  // namespace

std::string scene_truth_csv(const std::vector<SceneTruth>& objects) {
  std::string s = "kind,model,center_x,center_y,center_z,length,width,height,heading_deg,flags,points";
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) s += ",pose" + std::to_string(r) + std::to_string(c);
  s += "\n";
  for (const SceneTruth& t : objects) {
    s += std::string(scene_object_kind_name(t.kind)) + "," + t.model;
    for (int k = 0; k < 3; ++k) s += "," + number(t.center[k], kCoordinateDigits);
    for (int k = 0; k < 3; ++k) s += "," + number(t.extent[k], kCoordinateDigits);
    s += "," + number(t.heading_deg, 3) + "," + std::to_string(t.flags) + "," + std::to_string(t.points);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) s += "," + number(t.pose(r, c), c == 3 ? kCoordinateDigits : kPoseDigits);
    s += "\n";
  }
  return s;
}

bool write_scene_truth(const std::string& path, const std::vector<SceneTruth>& objects, std::string* error) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << scene_truth_csv(objects);
    f.close();
    if (!f) {
      std::remove(tmp.c_str());
      *error = path + ": cannot write the truth file";
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    *error = path + ": cannot write the truth file";
    return false;
  }
  return true;
}

}  // namespace spinhash::host
