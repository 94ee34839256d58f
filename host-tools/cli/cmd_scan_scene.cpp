// spinhash scan-scene MESHES... -o TILE.las: a simulated airborne tile (terrain,
// vehicles resting on it, clutter) with its truth (host-tools/scan/scene_simulator.hpp);
// with --length, a flight line of such tiles in scan order with GPS time
// (host-tools/scan/flight_line.hpp).
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud/cloud_writer.hpp"
#include "cloud/las_writer.hpp"
#include "pipeline/model_sources.hpp"
#include "scan/flight_line.hpp"
#include "scan/scan_simulator.hpp"
#include "scan/scene_simulator.hpp"
#include "survey/cut_tiles.hpp"

namespace spinhash::cli {
namespace {

struct ScanSceneArgs {
  std::vector<std::string> meshes;
  std::vector<std::string> unknown;
  std::string output;
  std::string truth;
  std::string tiles_out;  // also cut into LAS tiles here, when given
  double tile_size = 40.0;
  std::vector<double> offset;
  host::SceneOptions options;
  double length = 0.0;  // m: a flight line of --size tiles along +y (0: one tile)
  double speed = 60.0;  // m/s
};

constexpr const char* kCommand = "scan-scene";

bool load(const std::vector<std::string>& inputs, std::vector<host::Mesh>* out, std::string* error) {
  std::vector<pipeline::ModelMesh> models;
  if (!pipeline::load_model_meshes(inputs, &models, error, /*quiet=*/true)) return false;
  for (pipeline::ModelMesh& m : models) {
    m.mesh.name = m.name;  // the name the database knows it by
    out->push_back(std::move(m.mesh));
  }
  return true;
}

// A flight line in scan order: LAS with GPS time (PLY without).
int write_flight_line(const ScanSceneArgs& a, const std::vector<host::Mesh>& vehicles,
                      const std::vector<host::Mesh>& unknown, const std::string& truth) {
  host::FlightLineOptions line;
  line.segment = a.options;
  line.length = a.length;
  line.speed = a.speed;
  const host::FlightLineScan f = host::simulate_flight_line(vehicles, unknown, line);
  std::string error;
  if (!f.scan.ok()) {
    print_error(kCommand, f.scan.error);
    return kExitError;
  }
  const bool las = host::cloud_format_for(a.output) == host::CloudFormat::kLas;
  if (!(las ? host::write_las(a.output, f.scan.xyz, f.scan.classification, f.gps_time, &error)
            : host::write_cloud(a.output, f.scan.xyz, f.scan.classification, false, &error)) ||
      !host::write_scene_truth(truth, f.scan.objects, &error)) {
    print_error(kCommand, error);
    return kExitError;
  }
  std::fprintf(stderr,
               "spinhash scan-scene: %s: a %.0f m flight line of %u segments, %zu points in scan order "
               "(largest lag %.1f m), %zu objects; truth %s\n",
               a.output.c_str(), a.length, f.segments, f.scan.size(), f.max_lag, f.scan.objects.size(),
               truth.c_str());
  return kExitOk;
}

int run_scan_scene(ScanSceneArgs& a) {
  std::string error;
  if (host::cloud_format_for(a.output) == host::CloudFormat::kUnknown) {
    print_error(kCommand, a.output + ": unknown point-cloud extension (write .las or .ply)");
    return kExitError;
  }
  for (size_t i = 0; i < a.offset.size() && i < 3; ++i) a.options.offset[i] = a.offset[i];
  if (a.options.unknown_vehicles > 0 && a.unknown.empty()) {
    print_error(kCommand, "--unknown-vehicles needs --unknown MESHES (vehicles not in the database)");
    return kExitError;
  }
  std::vector<host::Mesh> vehicles, unknown;
  if (!load(a.meshes, &vehicles, &error) || (!a.unknown.empty() && !load(a.unknown, &unknown, &error))) {
    print_error(kCommand, error);
    return kExitError;
  }
  const std::string truth = a.truth.empty() ? a.output + ".truth.csv" : a.truth;
  if (a.length > 0.0) return write_flight_line(a, vehicles, unknown, truth);
  const host::SceneScan scan = host::simulate_scene(vehicles, unknown, a.options);
  if (!scan.ok()) {
    print_error(kCommand, scan.error);
    return kExitError;
  }
  if (!host::write_cloud(a.output, scan.xyz, scan.classification, false, &error) ||
      !host::write_scene_truth(truth, scan.objects, &error)) {
    print_error(kCommand, error);
    return kExitError;
  }
  if (!a.tiles_out.empty()) {
    survey::CutOptions cut;
    cut.size = a.tile_size;
    for (int k = 0; k < 2; ++k)  // the scene's square: its few stray hits beyond are left out
      cut.keep_min[k] = a.options.offset[k] - 0.5 * a.options.size,
      cut.keep_max[k] = a.options.offset[k] + 0.5 * a.options.size;
    const int n = survey::cut_into_tiles(scan.xyz, scan.classification, cut, a.tiles_out,
                                         host::cloud_name(a.output), &error);
    if (n < 0) {
      print_error(kCommand, error);
      return kExitError;
    }
    std::fprintf(stderr, "spinhash scan-scene: %d tiles of %g m in %s\n", n, a.tile_size,
                 a.tiles_out.c_str());
  }
  std::fprintf(stderr,
               "spinhash scan-scene: %s: %zu points from %u views (%llu rays), %zu objects; truth %s\n",
               a.output.c_str(), scan.size(), a.options.views, static_cast<unsigned long long>(scan.rays),
               scan.objects.size(), truth.c_str());
  return kExitOk;
}

}  // namespace

void add_scan_scene_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<ScanSceneArgs>();
  host::SceneOptions& o = a->options;
  CLI::App* cmd = app.add_subcommand(
      "scan-scene",
      "simulate an airborne lidar tile: sloped terrain, vehicles resting on it, clutter (LAS out)");
  cmd->add_option("meshes", a->meshes, "vehicle meshes of the database: files or folders")->required();
  cmd->add_option("-o,--output", a->output, "tile to write: .las (terrain classified 2, the rest 1) or .ply")
      ->required();
  cmd->add_option("--truth", a->truth,
                  "truth CSV: kind, model, centre, extent, pose per object (default OUTPUT.truth.csv)");
  cmd->add_option(
      "--tiles-out", a->tiles_out,
      "also cut the scene into LAS tiles on the absolute --tile-size lattice, written here (a survey)");
  cmd->add_option("--tile-size", a->tile_size, "side of the --tiles-out tiles, m")
      ->check(CLI::Range(survey::kMinTileSize, survey::kMaxTileSize))
      ->capture_default_str();
  cmd->add_option("--size", o.size, "tile side, m")
      ->check(CLI::Range(1.0, host::kMaxSceneSize))
      ->capture_default_str();
  cmd->add_option("--slope", o.slope_deg, "terrain slope, degrees (random direction)")
      ->check(CLI::Range(0.0, host::kMaxSceneSlopeDeg))
      ->capture_default_str();
  cmd->add_option("--bumps", o.bump_height, "largest terrain bump, m")
      ->check(CLI::Range(0.0, 50.0))
      ->capture_default_str();
  cmd->add_option("--curb", o.curb_height, "curb step, m")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--vehicles", o.vehicles, "vehicles from MESHES (two side by side, one under a tree)")
      ->check(CLI::Range(0u, host::kMaxSceneVehicles))
      ->capture_default_str();
  cmd->add_option("--parked-rows", o.parked_rows,
                  "rows of --row-length vehicles parked side by side (of --vehicles, after the pair)")
      ->check(CLI::Range(0u, host::kMaxSceneVehicles))
      ->capture_default_str();
  cmd->add_option("--row-length", o.row_length, "vehicles per parked row")
      ->check(CLI::Range(2u, 16u))
      ->capture_default_str();
  cmd->add_option("--length", a->length,
                  "a flight line of this many m along +y, of --size tiles, in scan order with GPS time "
                  "(0: one tile)")
      ->check(CLI::Range(0.0, host::kMaxFlightLineLength));
  cmd->add_option("--speed", a->speed, "the flight line's speed, m/s (its GPS time)")
      ->check(CLI::Range(1.0, 500.0))
      ->capture_default_str();
  cmd->add_option("--unknown", a->unknown, "meshes of vehicles not in the database: files or folders");
  cmd->add_option("--unknown-vehicles", o.unknown_vehicles, "vehicles drawn from --unknown")
      ->check(CLI::Range(0u, host::kMaxSceneVehicles))
      ->capture_default_str();
  cmd->add_option("--trees", o.trees, "trees (4-9 m; the first over a vehicle)")
      ->check(CLI::Range(0u, host::kMaxSceneClutter))
      ->capture_default_str();
  cmd->add_option("--buildings", o.buildings, "buildings (10-15 m)")
      ->check(CLI::Range(0u, host::kMaxSceneClutter))
      ->capture_default_str();
  cmd->add_option("--walls", o.walls, "walls (14 m)")
      ->check(CLI::Range(0u, host::kMaxSceneClutter))
      ->capture_default_str();
  cmd->add_option("--crates", o.crates, "crates (~1 m)")
      ->check(CLI::Range(0u, host::kMaxSceneClutter))
      ->capture_default_str();
  // Non-vehicles of a vehicle's size, none by default.
  const struct {
    const char* flag;
    uint32_t* count;
    const char* help;
  } sized[] = {{"--sheds", &o.sheds, "sheds and single garages (2.4-6.5 m, gabled)"},
               {"--containers", &o.containers, "freight containers (ISO 20 and 40 ft: 6.1 or 12.2 m)"},
               {"--bushes", &o.bushes, "bushes and hedges (1.5-6 m)"},
               {"--heaps", &o.heaps, "heaps of earth or covered loads (2.5-8 m)"}};
  for (const auto& kind : sized)
    cmd->add_option(kind.flag, *kind.count, kind.help)
        ->check(CLI::Range(0u, host::kMaxSceneClutter))
        ->capture_default_str();
  cmd->add_option("--views", o.views, "oblique viewpoints (elevation 45-60 degrees, range 100-200 m)")
      ->check(CLI::Range(1u, host::kMaxScanViews))
      ->capture_default_str();
  cmd->add_option("--spacing", o.point_spacing, "point spacing on level ground, all views together, m")
      ->check(CLI::Range(0.01, 10.0))
      ->capture_default_str();
  cmd->add_option("--noise", o.noise_sigma, "Gaussian noise along each ray, m")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "seed for terrain, layout, viewpoints and noise")->capture_default_str();
  cmd->add_option("--offset", a->offset, "georeferencing offset E N U (default 512000 5400000 300)")
      ->expected(3);
  cmd->callback([a, exit_code]() { *exit_code = run_scan_scene(*a); });
}

}  // namespace spinhash::cli
