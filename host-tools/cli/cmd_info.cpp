// spinhash info DB.shdb: what a database holds and how it was built.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/recognition_session.hpp"

namespace spinhash::cli {

using pipeline::DatabaseFile;
using pipeline::load_database;
using pipeline::model_name;
namespace {

void print_params(const Database& db, uint64_t bytes) {
  const blob::Params& p = db.params();
  std::printf("format        v%u, %llu bytes, %.1f bytes per feature, fingerprint %016llx\n",
              db.header().version, static_cast<unsigned long long>(bytes),
              static_cast<double>(bytes) / p.feature_count,
              static_cast<unsigned long long>(db.header().config_fingerprint));
  std::printf("models        %u\nfeatures      %u\n", p.model_count, p.feature_count);
  std::printf("spin images   %ux%u bins, R = %g m, support angle %g deg, quantisation scale %g\n",
              p.bins_alpha, p.bins_beta, static_cast<double>(p.support_radius),
              static_cast<double>(p.support_angle_deg), static_cast<double>(p.spin_quant_scale));
  std::printf("sampling      voxel %g m, normal radius %g m, basis spacing %g m\n",
              static_cast<double>(p.cloud_voxel), static_cast<double>(p.normal_radius),
              static_cast<double>(p.basis_spacing));
  std::printf("LSH           L = %u tables, K = %u bits, %u buckets per table, d_c = %g\n", p.lsh_tables,
              p.lsh_bits, p.lsh_buckets, static_cast<double>(p.lsh_dc));
  std::printf("model grids   %g m cells, %u offsets\n", static_cast<double>(p.grid_cell),
              p.grid_offset_count);
}

int run_info(const std::string& path) {
  DatabaseFile file;
  std::string error;
  if (!load_database(path, &file, &error)) {
    std::fprintf(stderr, "spinhash info: %s\n", error.c_str());
    return kExitError;
  }
  print_params(file.db, file.bytes.size());
  std::printf("%-24s %8s  %s\n", "model", "features", "extent x y z (m)");
  for (uint32_t m = 0; m < file.db.model_count(); ++m) {
    const blob::ModelRecord& r = file.db.model(m);
    std::printf("%-24s %8u  %.2f %.2f %.2f\n", model_name(file.db, m).c_str(), r.feature_count,
                static_cast<double>(r.bbox_max[0] - r.bbox_min[0]),
                static_cast<double>(r.bbox_max[1] - r.bbox_min[1]),
                static_cast<double>(r.bbox_max[2] - r.bbox_min[2]));
  }
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, int* exit_code) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("info", "describe a database blob");
  cmd->add_option("database", *path, "database file")->required();
  cmd->callback([path, exit_code]() { *exit_code = run_info(*path); });
}

}  // namespace spinhash::cli
