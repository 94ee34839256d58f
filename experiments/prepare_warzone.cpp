// spinhash-experiment prepare-warzone --base DIR -o OUT: Warzone 2100's PIE
// models (base.wz unpacked; scripts/prepare-warzone.sh fetches and unpacks
// it) to OBJ meshes Assimp reads, in the generator's frame (metres, x
// forward, z up, ground at z = 0, centred): OUT/vehicles (body + propulsion
// assembled, and the one-piece vehicles), OUT/structures and OUT/features
// (map features: trees, rocks, wrecks, ruins), plus OUT/catalog.csv (the
// vehicles' classes; empty for structures and features, not vehicles) and
// OUT/vehicle-classes.txt, the vehicles' classes as a `spinhash build
// --classes` manifest. The data is GPL game content: never commit it.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "csv_table.hpp"
#include "experiments.hpp"
#include "mesh/mesh_writer.hpp"
#include "mesh/pie_reader.hpp"
#include "output_dir.hpp"
#include "pipeline/exit_codes.hpp"
#include "warzone_catalog.hpp"
#include "world_mesh.hpp"

namespace spinhash::experiment {
namespace {

namespace fs = std::filesystem;

constexpr double kMinObjectHeight = 0.5;  // m: flat footprints and decals are not objects

struct PrepareArgs {
  std::string base;
  std::string out;
  bool structures = true;
  bool features = true;
};

struct Tally {
  uint32_t written = 0;
  uint32_t skipped = 0;
};

bool load_parts(const std::string& base, const std::vector<std::string>& parts, host::Mesh* out,
                std::string* error) {
  for (const std::string& p : parts) {
    host::Mesh part;
    host::PieInfo info;
    if (!host::read_pie((fs::path(base) / p).string(), &part, &info, error)) {
      *error = p + ": " + *error;
      return false;
    }
    out->append(part);
  }
  out->apply_transform(host::pie_to_metres());
  settle(out);
  return true;
}

bool write_one(const std::string& dir, const std::string& klass, const std::string& kind, host::Mesh& m,
               CsvTable* catalog, std::string* error, const std::string& group = "") {
  const std::string path = (fs::path(dir) / (m.name + ".obj")).string();
  if (!host::write_obj(path, m, error)) return false;
  catalog->add(catalog_row(m, klass, "warzone-" + kind, group));
  return true;
}

bool prepare_vehicles(const PrepareArgs& a, CsvTable* catalog, Tally* tally, std::string* error) {
  const std::string out = a.out + "/vehicles";
  if (!make_output_dir(out, error)) return false;
  std::string manifest = "# MODEL_NAME CLASS [GROUP]: spinhash build --classes (Warzone 2100 vehicles)\n";
  for (const WarzoneVehicle& v : warzone_vehicles()) {
    host::Mesh m;
    if (!load_parts(a.base, v.parts, &m, error)) return false;
    m.name = v.name;
    if (!write_one(out, v.klass, "vehicle", m, catalog, error, v.group)) return false;
    manifest += v.name + " " + v.klass + (v.group.empty() ? "" : " " + v.group) + "\n";
    ++tally->written;
  }
  return write_text(a.out + "/vehicle-classes.txt", manifest, error);
}

// Every one-piece model of base/subdir that stands at least kMinObjectHeight
// tall and is not a texture variant, as OUT/kind + "s"/prefix + stem.obj.
bool prepare_directory(const PrepareArgs& a, const char* subdir, const std::string& kind,
                       const std::string& prefix, CsvTable* catalog, Tally* tally, std::string* error) {
  const std::string out = a.out + "/" + kind + "s";
  const fs::path dir = fs::path(a.base) / subdir;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".pie") files.push_back(e.path());
  if (ec) {
    *error = dir.string() + ": " + ec.message();
    return false;
  }
  if (!make_output_dir(out, error)) return false;
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    const std::string stem = f.stem().string();
    host::Mesh m;
    std::string why;
    if (is_texture_variant(stem) || !load_parts(a.base, {fs::relative(f, a.base).string()}, &m, &why) ||
        m.bounding_box().size().z() < kMinObjectHeight) {
      if (!why.empty())
        std::fprintf(stderr, "spinhash-experiment prepare-warzone: skipped %s\n", why.c_str());
      ++tally->skipped;
      continue;
    }
    m.name = prefix + stem;
    if (!write_one(out, "", kind, m, catalog, error)) return false;
    ++tally->written;
  }
  return true;
}

int run_prepare(const PrepareArgs& a) {
  std::string error;
  CsvTable catalog(catalog_header());
  Tally tally;
  const bool ok = prepare_vehicles(a, &catalog, &tally, &error) &&
                  (!a.structures || prepare_directory(a, kWarzoneStructureDir, "structure", "wzs-", &catalog,
                                                      &tally, &error)) &&
                  (!a.features ||
                   prepare_directory(a, kWarzoneFeatureDir, "feature", "wzf-", &catalog, &tally, &error)) &&
                  catalog.write(a.out + "/catalog.csv", &error);
  if (!ok) {
    std::fprintf(stderr, "spinhash-experiment prepare-warzone: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::fprintf(stderr,
               "spinhash-experiment prepare-warzone: %u meshes in %s (%u skipped: texture variants, "
               "flat or unreadable)\n",
               tally.written, a.out.c_str(), tally.skipped);
  return pipeline::kExitOk;
}

}  // namespace

void add_prepare_warzone(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<PrepareArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "prepare-warzone",
      "Warzone 2100 PIE models (unpacked base.wz) to OBJ vehicles, structures and features");
  cmd->add_option("--base", a->base, "the unpacked base.wz (holds components/, structs/ and features/)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", a->out, "output folder")->required();
  cmd->add_flag("!--no-structures", a->structures, "leave out the structures");
  cmd->add_flag("!--no-features", a->features, "leave out the map features (trees, rocks, wrecks, ruins)");
  cmd->callback([a, exit_code]() { *exit_code = run_prepare(*a); });
}

}  // namespace spinhash::experiment
