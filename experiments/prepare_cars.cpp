// spinhash-experiment prepare-cars --torcs DIR --trigger DIR -o OUT: an
// independent test world of real car meshes, never tuned on:
// TORCS' 17 car bodies (Debian's torcs-data, AC3D .acc, loaded y up by
// Assimp) and Trigger Rally's 3 distinct bodies (trigger-rally-data, OBJ in
// centimetres, wheels placed from the .vehicle file; its 9 vehicles are 3
// bodies in 3 liveries of the same geometry, so one of each), written as
// OBJ in the generator's frame (metres, x forward, z up, ground at z = 0,
// centred) under OUT/<class>/ so that `build` and `--meshes` read the class
// from the folder, plus OUT/catalog.csv. Game content: never commit it.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "csv_table.hpp"
#include "experiments.hpp"
#include "mesh/mesh_loader.hpp"
#include "output_dir.hpp"
#include "pipeline/exit_codes.hpp"
#include "world_mesh.hpp"

namespace spinhash::experiment {
namespace {

namespace fs = std::filesystem;

struct CarEntry {
  const char* name;        // the source's folder and stem
  const char* klass;       // vehicle class folder (include/spinhash/vehicle_classes.h)
  const char* group = "";  // the car's group where its class has none ("": its class's)
};

// TORCS 1.3.7: touring, stock and GT cars are sedans (saloon or coupe
// bodies); the buggies and the open-wheel racer are "other", each a car of
// well under a tonne, so a light vehicle.
constexpr CarEntry kTorcsCars[] = {
    {"155-DTM", "sedan"},
    {"acura-nsx-sz", "sedan"},
    {"baja-bug", "other", "light"},
    {"buggy", "other", "light"},
    {"car1-ow1", "other", "light"},
    {"car1-stock1", "sedan"},
    {"car1-stock2", "sedan"},
    {"car1-trb1", "sedan"},
    {"car1-trb3", "sedan"},
    {"car2-trb1", "sedan"},
    {"car3-trb1", "sedan"},
    {"car4-trb1", "sedan"},
    {"car5-trb1", "sedan"},
    {"car6-trb1", "sedan"},
    {"car7-trb1", "sedan"},
    {"car8-trb1", "sedan"},
    {"p406", "sedan"},
};
// Trigger Rally 0.6.6: rally hatchbacks; kitcar and super500 share the wrc's geometry.
constexpr CarEntry kTriggerCars[] = {{"cordo_wrc", "sedan"}, {"evo_wrc", "sedan"}, {"fox_wrc", "sedan"}};

struct PrepareArgs {
  std::string torcs;    // .../games/torcs/cars
  std::string trigger;  // data.zip's vehicles/ unpacked
  std::string out;
};

// Assimp reads AC3D y up: a quarter turn about x puts its y on z.
bool load_torcs(const std::string& dir, const CarEntry& c, host::Mesh* m, std::string* error) {
  if (!host::load_mesh((fs::path(dir) / c.name / (std::string(c.name) + ".acc")).string(), m, error))
    return false;
  m->apply_transform(
      linear_transform(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix()));
  return true;
}

struct WheelSpec {
  Eigen::Vector3d pos;
  double radius = 0.0;
};

// The value of attribute `name` in the XML tag that starts at `at` (up to
// its '>'); false when the tag has none. (No std::regex: GCC 12 warns
// inside <regex> under the sanitizers' -Werror build.)
bool tag_attribute(const std::string& s, size_t at, const std::string& name, std::string* value) {
  const size_t end = s.find('>', at);
  const std::string key = name + "=\"";
  for (size_t k = s.find(key, at); k != std::string::npos && k < end; k = s.find(key, k + 1)) {
    if (!std::isspace(static_cast<unsigned char>(s[k - 1]))) continue;  // another attribute's tail
    const size_t from = k + key.size(), to = s.find('"', from);
    if (to == std::string::npos || to > end) return false;
    *value = s.substr(from, to - from);
    return true;
  }
  return false;
}

// Numbers separated by commas (and spaces): "1.2, -0.5, 3".
std::vector<double> numbers(const std::string& text) {
  std::vector<double> v;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) v.push_back(std::stod(item));
  return v;
}

// The body part's scale and its wheels from a Trigger .vehicle (XML).
bool read_vehicle(const std::string& path, double* scale, std::vector<WheelSpec>* wheels,
                  std::string* error) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::string value;
  bool found = false;
  for (size_t at = s.find("<part"); at != std::string::npos && !found; at = s.find("<part", at + 1))
    found = tag_attribute(s, at, "scale", &value);
  if (!found) {
    *error = path + ": no <part scale=...>";
    return false;
  }
  *scale = std::stod(value);
  for (size_t at = s.find("<wheel"); at != std::string::npos; at = s.find("<wheel", at + 1)) {
    std::string pos, radius;
    if (!tag_attribute(s, at, "pos", &pos) || !tag_attribute(s, at, "radius", &radius)) continue;
    const std::vector<double> p = numbers(pos);
    if (p.size() == 3) wheels->push_back(WheelSpec{{p[0], p[1], p[2]}, std::stod(radius)});
  }
  if (wheels->empty()) {
    *error = path + ": no <wheel pos=... radius=...>";
    return false;
  }
  return true;
}

// Body scaled to metres, each wheel mesh scaled to its radius and centred on
// its position, then y forward turned to x forward.
bool load_trigger(const std::string& dir, const CarEntry& c, host::Mesh* m, std::string* error) {
  const fs::path base = fs::path(dir) / c.name;
  double scale = 0.0;
  std::vector<WheelSpec> wheels;
  host::Mesh wheel;
  if (!read_vehicle((base / (std::string(c.name) + ".vehicle")).string(), &scale, &wheels, error) ||
      !host::load_mesh((base / (std::string(c.name) + ".obj")).string(), m, error) ||
      !host::load_mesh((base / (std::string(c.name) + "_wheel.obj")).string(), &wheel, error))
    return false;
  m->apply_transform(linear_transform(Eigen::Matrix3d::Identity() * scale));
  const host::Box3 wb = wheel.bounding_box();
  const double wheel_radius = 0.5 * std::max(wb.size().y(), wb.size().z());
  for (const WheelSpec& w : wheels) {
    host::Mesh one = wheel;
    Eigen::Matrix4d t = linear_transform(Eigen::Matrix3d::Identity() * (w.radius / wheel_radius));
    t.topRightCorner<3, 1>() = w.pos - wb.center() * (w.radius / wheel_radius);
    one.apply_transform(t);
    m->append(one);
  }
  m->apply_transform(
      linear_transform(Eigen::AngleAxisd(-0.5 * M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix()));
  return true;
}

bool write_one(const std::string& out, const CarEntry& c, const std::string& source, host::Mesh* m,
               CsvTable* catalog, std::string* error) {
  settle(m);
  m->name = c.name;
  return write_in_class_folder(out, c.klass, source, *m, catalog, error, c.group);
}

int run_prepare(const PrepareArgs& a) {
  std::string error;
  CsvTable catalog(catalog_header());
  uint32_t written = 0;
  bool ok = make_output_dir(a.out, &error);
  for (const CarEntry& c : kTorcsCars) {
    host::Mesh m;
    ok = ok && load_torcs(a.torcs, c, &m, &error) && write_one(a.out, c, "torcs", &m, &catalog, &error);
    written += ok ? 1u : 0u;
  }
  for (const CarEntry& c : kTriggerCars) {
    if (a.trigger.empty()) break;
    host::Mesh m;
    ok = ok && load_trigger(a.trigger, c, &m, &error) && write_one(a.out, c, "trigger", &m, &catalog, &error);
    written += ok ? 1u : 0u;
  }
  ok = ok && catalog.write(a.out + "/catalog.csv", &error);
  if (!ok) {
    std::fprintf(stderr, "spinhash-experiment prepare-cars: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::fprintf(stderr, "spinhash-experiment prepare-cars: %u car meshes in %s\n", written, a.out.c_str());
  return pipeline::kExitOk;
}

}  // namespace

void add_prepare_cars(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<PrepareArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "prepare-cars",
      "TORCS and Trigger Rally car bodies to OBJ meshes in class folders (the independent set)");
  cmd->add_option("--torcs", a->torcs, "TORCS' cars/ folder (torcs-data)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--trigger", a->trigger,
                  "Trigger Rally's vehicles/ folder (data.zip of trigger-rally-data)")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", a->out, "output folder")->required();
  cmd->callback([a, exit_code]() { *exit_code = run_prepare(*a); });
}

}  // namespace spinhash::experiment
