#include "pipeline/model_classes.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace spinhash::pipeline {
namespace {

bool class_named(const std::string& word, VehicleClass* out) {
  return parse_vehicle_class(word.c_str(), out);
}

std::string class_list() {
  std::string s;
  for (uint32_t id = 0; id < kVehicleClassCount; ++id)
    s += (id ? ", " : "") + std::string(vehicle_class_name(id));
  return s;
}

std::string group_list() {
  std::string s;
  for (uint32_t id = 0; id < kVehicleGroupCount; ++id)
    s += (id ? ", " : "") + std::string(vehicle_group_name(id));
  return s;
}

// One manifest line into `name`, `cls` and `group`, the model's own group
// (kNone without a third word, or where it repeats the class's: the blob
// stores one way to say it); false for a blank line or a comment, *why set
// when the line is not "NAME CLASS [GROUP]" with a known class and a group
// its class allows.
bool parse_line(const std::string& line, std::string* name, VehicleClass* cls, VehicleGroup* group,
                std::string* why) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::string word, group_word, extra;
  if (!(in >> *name)) return false;  // blank or comment
  if (!(in >> word) || ((in >> group_word) && (in >> extra))) {
    *why = "expected 'MODEL_NAME CLASS [GROUP]'";
    return true;
  }
  if (!class_named(word, cls)) {
    *why = "unknown class '" + word + "' (classes: " + class_list() + ")";
  } else if (!group_word.empty() && !parse_vehicle_group(group_word.c_str(), group)) {
    *why = "unknown group '" + group_word + "' (groups: " + group_list() + ")";
  } else if (vehicle_group_of(*cls) != VehicleGroup::kNone) {
    if (!group_word.empty() && *group != vehicle_group_of(*cls))
      *why = "class '" + word + "' is in group '" + vehicle_group_name(vehicle_group_of(*cls)) +
             "': only a class in no group takes a group per model";
    *group = VehicleGroup::kNone;
  }
  return true;
}

}  // namespace

VehicleClass class_from_name(const std::string& name) {
  VehicleClass c = VehicleClass::kUnclassified;
  class_named(name.substr(0, name.find_first_of("-_")), &c);
  return c;
}

VehicleClass class_of_file(const std::string& path) {
  const std::filesystem::path p(path);
  VehicleClass c = VehicleClass::kUnclassified;
  if (class_named(p.parent_path().filename().string(), &c)) return c;
  return class_from_name(p.stem().string());
}

bool apply_class_manifest(const std::string& path, std::vector<host::ModelCloud>* models,
                          std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = path + ": cannot read the class manifest";
    return false;
  }
  std::map<std::string, host::ModelCloud*> by_name;
  for (host::ModelCloud& m : *models) by_name[m.name] = &m;
  std::set<std::string> seen;
  std::string line, problems;
  for (uint32_t n = 1; std::getline(in, line); ++n) {
    std::string name, why;
    VehicleClass cls = VehicleClass::kUnclassified;
    VehicleGroup group = VehicleGroup::kNone;
    if (!parse_line(line, &name, &cls, &group, &why)) continue;
    if (why.empty() && by_name.count(name) == 0) why = "no model named '" + name + "'";
    if (why.empty() && !seen.insert(name).second) why = "model '" + name + "' named twice";
    if (!why.empty()) {
      problems += path + ":" + std::to_string(n) + ": " + why + "\n";
      continue;
    }
    by_name[name]->vehicle_class = cls;
    by_name[name]->vehicle_group = group;
  }
  if (problems.empty()) return true;
  *error = problems.substr(0, problems.size() - 1);
  return false;
}

}  // namespace spinhash::pipeline
