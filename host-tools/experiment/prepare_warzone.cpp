// spinhash experiment prepare-warzone --base DIR -o OUT: Warzone 2100's PIE
// models (base.wz unpacked; scripts/prepare-warzone.sh fetches and unpacks
// it) to OBJ meshes Assimp reads, in the generator's frame (metres, x
// forward, z up, ground at z = 0, centred): OUT/vehicles (body + propulsion
// assembled, and the one-piece vehicles) and OUT/structures, plus
// OUT/catalog.csv. The data is GPL game content: never commit it.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "experiment/csv_table.hpp"
#include "experiment/experiments.hpp"
#include "experiment/output_dir.hpp"
#include "experiment/warzone_catalog.hpp"
#include "mesh/mesh_writer.hpp"
#include "mesh/pie_reader.hpp"

namespace spinhash::experiment {
namespace {

namespace fs = std::filesystem;

constexpr double kMinStructureHeight = 0.5;  // m: flat footprints and decals are not objects

struct PrepareArgs {
  std::string base;
  std::string out;
  bool structures = true;
};

// Ground at z = 0, footprint centred on the origin.
void settle(host::Mesh* m) {
  host::Box3 b = m->bounding_box();
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topRightCorner<3, 1>() = Eigen::Vector3d(-b.center().x(), -b.center().y(), -b.lo.z());
  m->apply_transform(t);
}

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

bool write_one(const std::string& dir, const std::string& kind, host::Mesh& m, CsvTable* catalog,
               std::string* error) {
  const std::string path = (fs::path(dir) / (m.name + ".obj")).string();
  if (!host::write_obj(path, m, error)) return false;
  const Eigen::Vector3d size = m.bounding_box().size();
  catalog->add({m.name, kind, std::to_string(m.triangle_count()), num(size.x(), 3), num(size.y(), 3),
                num(size.z(), 3)});
  return true;
}

int run_prepare(const PrepareArgs& a) {
  std::string error;
  const std::string vehicles = a.out + "/vehicles", structures = a.out + "/structures";
  CsvTable catalog({"name", "kind", "triangles", "length_m", "width_m", "height_m"});
  uint32_t written = 0, skipped = 0;
  bool ok = make_output_dir(vehicles, &error) && (!a.structures || make_output_dir(structures, &error));
  for (const WarzoneVehicle& v : warzone_vehicles()) {
    host::Mesh m;
    m.name = v.name;
    if (!ok || !load_parts(a.base, v.parts, &m, &error)) break;
    m.name = v.name;
    ok = write_one(vehicles, "vehicle", m, &catalog, &error);
    written += ok ? 1u : 0u;
  }
  const fs::path sdir = fs::path(a.base) / kWarzoneStructureDir;
  std::vector<fs::path> files;
  if (ok && a.structures) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(sdir, ec))
      if (e.path().extension() == ".pie") files.push_back(e.path());
    if (ec) {
      error = sdir.string() + ": " + ec.message();
      ok = false;
    }
    std::sort(files.begin(), files.end());
  }
  for (const fs::path& f : files) {
    if (!ok) break;
    const std::string stem = f.stem().string();
    host::Mesh m;
    std::string why;
    if (is_texture_variant(stem) || !load_parts(a.base, {fs::relative(f, a.base).string()}, &m, &why) ||
        m.bounding_box().size().z() < kMinStructureHeight) {
      if (!why.empty()) std::fprintf(stderr, "spinhash experiment prepare-warzone: skipped %s\n", why.c_str());
      ++skipped;
      continue;
    }
    m.name = "wzs-" + stem;
    ok = write_one(structures, "structure", m, &catalog, &error);
    written += ok ? 1u : 0u;
  }
  if (!ok || !catalog.write(a.out + "/catalog.csv", &error)) {
    std::fprintf(stderr, "spinhash experiment prepare-warzone: %s\n", error.c_str());
    return cli::kExitError;
  }
  std::fprintf(stderr, "spinhash experiment prepare-warzone: %u meshes in %s (%u structures skipped: texture "
               "variants, flat or unreadable)\n", written, a.out.c_str(), skipped);
  return cli::kExitOk;
}

}  // namespace

void add_prepare_warzone(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<PrepareArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "prepare-warzone", "Warzone 2100 PIE models (unpacked base.wz) to OBJ vehicles and structures");
  cmd->add_option("--base", a->base, "the unpacked base.wz (holds components/ and structs/)")
      ->required()->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", a->out, "output folder")->required();
  cmd->add_flag("!--no-structures", a->structures, "vehicles only");
  cmd->callback([a, exit_code]() { *exit_code = run_prepare(*a); });
}

}  // namespace spinhash::experiment
