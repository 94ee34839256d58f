// spinhash-experiment prepare-sweethome3d --furniture DIR -o OUT: a test
// world of real-vehicle meshes from Debian's sweethome3d-furniture (Sweet
// Home 3D's additional furniture libraries, OBJ, CC-BY 3.0 and CC0), made by
// other artists than any other world the project uses: only ever a left-out
// test world, never tuned on. DIR holds the libraries' .sh3f archives
// unzipped, one folder each (scripts/prepare-sweethome3d.sh). The
// vehicles are written as OBJ in the generator's frame (metres, x forward,
// z up, ground at z = 0, centred) under OUT/<class>/, so that `build` and
// `--meshes` read the class from the folder, plus OUT/catalog.csv. Licensed
// content: never commit it.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "csv_table.hpp"
#include "experiments.hpp"
#include "mesh/mesh_loader.hpp"
#include "output_dir.hpp"
#include "pipeline/exit_codes.hpp"
#include "world_mesh.hpp"

namespace spinhash::experiment {
namespace {

namespace fs = std::filesystem;

// Sweet Home 3D models are y up. Which way the vehicle's front faces.
enum class Front { kPlusZ, kMinusX };

struct Sh3dEntry {
  const char* library;  // the .sh3f archive's name, its folder under DIR
  const char* stem;     // the model's OBJ stem (model#N=/.../stem/stem.obj)
  const char* name;     // the mesh's name in this world
  const char* klass;    // vehicle class folder (include/spinhash/vehicle_classes.h)
  Front front;
};

// Every road vehicle of the libraries (category "Vehicles"), bicycles,
// scooters, motorbikes, prams and skateboards left out. "Concept Sedan 01"
// comes twice with the same geometry (v1, v2): one of them. The Renault
// Scenic is an MPV (van); the Chevrolet a sports coupe and the Smart a
// city car (sedan: passenger cars); the Peterbilt and the DAF are tractor
// units with their semi-trailers (21 m and 16.5 m), the Scopia truck a
// three-axle box lorry; the forklift is "other".
constexpr Sh3dEntry kEntries[] = {
    {"BlendSwap-CC-BY", "fordFocus", "sh3d-ford-focus", "sedan", Front::kPlusZ},
    {"KatorLegaz", "concept-sedan-01v1", "sh3d-concept-sedan-01", "sedan", Front::kPlusZ},
    {"KatorLegaz", "concept-sedan-02", "sh3d-concept-sedan-02", "sedan", Front::kPlusZ},
    {"KatorLegaz", "concept-sedan-02-sport", "sh3d-concept-sedan-02-sport", "sedan", Front::kPlusZ},
    {"KatorLegaz", "VW-new-beetle", "sh3d-vw-new-beetle", "sedan", Front::kPlusZ},
    {"Scopia", "seat_leon", "sh3d-seat-leon", "sedan", Front::kPlusZ},
    {"Scopia", "peugeot-308", "sh3d-peugeot-308-cc", "sedan", Front::kPlusZ},
    {"Scopia", "chevrolet", "sh3d-chevrolet", "sedan", Front::kPlusZ},
    {"Scopia", "smart-car", "sh3d-smart", "sedan", Front::kPlusZ},
    {"Scopia", "suv", "sh3d-suv", "suv", Front::kPlusZ},
    {"Scopia", "renault-scenic", "sh3d-renault-scenic", "van", Front::kPlusZ},
    {"Scopia", "van", "sh3d-van", "van", Front::kPlusZ},
    {"Scopia", "truck", "sh3d-truck", "truck", Front::kPlusZ},
    {"BlendSwap-CC-0", "peterbilt", "sh3d-peterbilt", "truck", Front::kPlusZ},
    {"BlendSwap-CC-BY", "dafTruck", "sh3d-daf", "truck", Front::kPlusZ},
    {"Scopia", "bus", "sh3d-coach", "bus", Front::kPlusZ},
    {"Scopia", "cityBus", "sh3d-city-bus", "bus", Front::kPlusZ},
    {"BlendSwap-CC-0", "forkLift", "sh3d-forklift", "other", Front::kMinusX},
};

constexpr double kCentimetre = 0.01;

struct PrepareArgs {
  std::string furniture;
  std::string out;
};

// The catalog's size of a model (cm): width (x), depth (z), height (y) of
// the entry whose model#N is /.../stem/stem.obj.
struct CatalogSize {
  double width = 0.0;
  double depth = 0.0;
  double height = 0.0;
  std::string model;  // the model path inside the library folder
};

bool read_catalog_size(const std::string& library_dir, const std::string& stem, CatalogSize* size,
                       std::string* error) {
  const std::string path = library_dir + "/PluginFurnitureCatalog.properties";
  std::ifstream in(path);
  if (!in) {
    *error = path + ": cannot read";
    return false;
  }
  // key#N=value lines; the entry's N is that of its model line.
  std::vector<std::pair<std::string, std::string>> lines;
  std::string id;
  const std::string suffix = "/" + stem + "/" + stem + ".obj";
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    lines.emplace_back(key, value);
    if (key.rfind("model#", 0) == 0 && value.size() >= suffix.size() &&
        value.compare(value.size() - suffix.size(), suffix.size(), suffix) == 0) {
      id = key.substr(6);
      size->model = value;
    }
  }
  if (id.empty()) {
    *error = path + ": no model " + stem;
    return false;
  }
  for (const auto& [key, value] : lines) {
    if (key == "width#" + id) size->width = std::stod(value);
    if (key == "depth#" + id) size->depth = std::stod(value);
    if (key == "height#" + id) size->height = std::stod(value);
  }
  if (!(size->width > 0.0 && size->depth > 0.0 && size->height > 0.0)) {
    *error = path + ": no width, depth and height for " + stem;
    return false;
  }
  return true;
}

// Loads an entry, turns it x forward and z up, and scales it uniformly so
// that its length is the catalog's (Sweet Home 3D shows it at that size;
// the catalogs' sizes are uniform scalings of the models).
bool load_entry(const std::string& dir, const Sh3dEntry& e, host::Mesh* m, std::string* error) {
  const std::string library = dir + "/" + e.library;
  CatalogSize size;
  if (!read_catalog_size(library, e.stem, &size, error) || !host::load_mesh(library + size.model, m, error))
    return false;
  Eigen::Matrix3d r;
  if (e.front == Front::kPlusZ)
    r << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // x = z, y = x, z = y
  else
    r << -1, 0, 0, 0, 0, 1, 0, 1, 0;  // x = -x, y = z, z = y
  m->apply_transform(linear_transform(r));
  const double length = m->bounding_box().size().x();
  const double catalog_length = (e.front == Front::kPlusZ ? size.depth : size.width) * kCentimetre;
  if (!(length > 0.0)) {
    *error = library + size.model + ": no length";
    return false;
  }
  m->apply_transform(linear_transform(Eigen::Matrix3d::Identity() * (catalog_length / length)));
  settle(m);
  m->name = e.name;
  return true;
}

int run_prepare(const PrepareArgs& a) {
  std::string error;
  CsvTable catalog(catalog_header());
  uint32_t written = 0;
  bool ok = make_output_dir(a.out, &error);
  for (const Sh3dEntry& e : kEntries) {
    host::Mesh m;
    ok = ok && load_entry(a.furniture, e, &m, &error) &&
         write_in_class_folder(a.out, e.klass, std::string("sweethome3d-") + e.library, m, &catalog, &error);
    if (!ok) break;
    ++written;
  }
  ok = ok && catalog.write(a.out + "/catalog.csv", &error);
  if (!ok) {
    std::fprintf(stderr, "spinhash-experiment prepare-sweethome3d: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::fprintf(stderr, "spinhash-experiment prepare-sweethome3d: %u vehicle meshes in %s\n", written,
               a.out.c_str());
  return pipeline::kExitOk;
}

}  // namespace

void add_prepare_sweethome3d(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<PrepareArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "prepare-sweethome3d",
      "Sweet Home 3D's furniture-library vehicles to OBJ meshes in class folders (a left-out test world)");
  cmd->add_option("--furniture", a->furniture,
                  "folder of the unzipped .sh3f libraries (sweethome3d-furniture), one folder each")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", a->out, "output folder")->required();
  cmd->callback([a, exit_code]() { *exit_code = run_prepare(*a); });
}

}  // namespace spinhash::experiment
