// spinhash info DB.shdb [--format text|json]: what a database holds and how it was built.
#include <cstdio>
#include <memory>

#include "cli/calibration_report.hpp"
#include "cli/commands.hpp"
#include "cli/json_line.hpp"
#include "cli/report_keys.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/recognition_session.hpp"

namespace spinhash::cli {

using pipeline::DatabaseFile;
using pipeline::load_database;
using pipeline::model_name;
namespace {

struct InfoArgs {
  std::string path;
  std::string format = "text";
};

double bytes_per_feature(const Database& db, uint64_t bytes) {
  return static_cast<double>(bytes) / db.params().feature_count;
}

std::string fingerprint_hex(const Database& db) {
  char hex[24];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(db.header().config_fingerprint));
  return hex;
}

void print_params(const Database& db, uint64_t bytes) {
  const blob::Params& p = db.params();
  std::printf("format        v%u, %llu bytes, %.1f bytes per feature, fingerprint %s\n", db.header().version,
              static_cast<unsigned long long>(bytes), bytes_per_feature(db, bytes),
              fingerprint_hex(db).c_str());
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
  if (db.has_nearest_field())
    std::printf("nearest field %g m voxels, reach %g m, %u slots, %u entries (%.1f MB)\n",
                static_cast<double>(p.field_cell), static_cast<double>(p.field_reach), p.field_slots,
                p.field_entry_count, 2.0e-6 * p.field_entry_count);
  else
    std::printf("nearest field none (verification searches the model grids)\n");
}

void print_text(const Database& db, uint64_t bytes) {
  print_params(db, bytes);
  std::printf("%-24s %-12s %-9s %8s  %s\n", "model", "class", "group", "features", "extent x y z (m)");
  for (uint32_t m = 0; m < db.model_count(); ++m) {
    const blob::ModelRecord& r = db.model(m);
    std::printf("%-24s %-12s %-9s %8u  %.2f %.2f %.2f\n", model_name(db, m).c_str(),
                vehicle_class_name(r.vehicle_class), vehicle_group_name(model_group(r)), r.feature_count,
                static_cast<double>(r.bbox_max[0] - r.bbox_min[0]),
                static_cast<double>(r.bbox_max[1] - r.bbox_min[1]),
                static_cast<double>(r.bbox_max[2] - r.bbox_min[2]));
  }
  print_calibration(db.calibration());
}

std::string num(float v) { return json_number(static_cast<double>(v), 7); }
std::string num(uint64_t v) { return std::to_string(v); }
std::string num(uint32_t v) { return std::to_string(v); }

std::string model_list_json(const Database& db) {
  namespace k = info_keys;
  std::vector<std::string> models;
  for (uint32_t m = 0; m < db.model_count(); ++m) {
    const blob::ModelRecord& r = db.model(m);
    models.push_back(json_object(
        {json_member(k::kName, json_string(model_name(db, m))),
         json_member(k::kClass, json_string(vehicle_class_name(r.vehicle_class))),
         json_member(k::kGroup, json_string(vehicle_group_name(model_group(r)))),
         json_member(k::kFeatures, num(r.feature_count)),
         json_member(k::kExtent, json_array(std::vector<std::string>{num(r.bbox_max[0] - r.bbox_min[0]),
                                                                     num(r.bbox_max[1] - r.bbox_min[1]),
                                                                     num(r.bbox_max[2] - r.bbox_min[2])}))}));
  }
  return json_array(models);
}

// One line: the text report's content under the keys of report_keys.hpp.
std::string info_json(const Database& db, uint64_t bytes) {
  namespace k = info_keys;
  const blob::Params& p = db.params();
  return json_object(
      {json_member(k::kFormat, num(db.header().version)), json_member(k::kBytes, num(bytes)),
       json_member(k::kBytesPerFeature, json_number(bytes_per_feature(db, bytes), 6)),
       json_member(k::kFingerprint, json_string(fingerprint_hex(db))),
       json_member(k::kModels, num(p.model_count)), json_member(k::kFeatures, num(p.feature_count)),
       json_member(k::kSpinImages,
                   json_object({json_member(k::kBins, json_array(std::vector<std::string>{num(p.bins_alpha),
                                                                                          num(p.bins_beta)})),
                                json_member(k::kRadius, num(p.support_radius)),
                                json_member(k::kSupportAngle, num(p.support_angle_deg)),
                                json_member(k::kQuantScale, num(p.spin_quant_scale))})),
       json_member(k::kSampling, json_object({json_member(k::kVoxel, num(p.cloud_voxel)),
                                              json_member(k::kNormalRadius, num(p.normal_radius)),
                                              json_member(k::kBasisSpacing, num(p.basis_spacing))})),
       json_member(
           k::kLsh,
           json_object({json_member(k::kTables, num(p.lsh_tables)), json_member(k::kBits, num(p.lsh_bits)),
                        json_member(k::kBuckets, num(p.lsh_buckets)), json_member(k::kDc, num(p.lsh_dc))})),
       json_member(k::kGrid, json_object({json_member(k::kCell, num(p.grid_cell)),
                                          json_member(k::kOffsets, num(p.grid_offset_count))})),
       json_member(k::kField, json_object({json_member(k::kCell, num(p.field_cell)),
                                           json_member(k::kReach, num(p.field_reach)),
                                           json_member(k::kSlots, num(p.field_slots)),
                                           json_member(k::kEntries, num(p.field_entry_count))})),
       json_member(k::kModelList, model_list_json(db)),
       json_member(k::kCalibration, calibration_json(db.calibration())), json_version_member()});
}

int run_info(const InfoArgs& a) {
  DatabaseFile file;
  std::string error;
  if (!load_database(a.path, &file, &error)) {
    std::fprintf(stderr, "spinhash info: %s\n", error.c_str());
    return kExitError;
  }
  if (a.format == "json")
    std::printf("%s\n", info_json(file.db, file.bytes.size()).c_str());
  else
    print_text(file.db, file.bytes.size());
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand("info", "describe a database blob");
  cmd->add_option("database", a->path, "database file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--format", a->format, "text, or json: one JSON object on one line")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  cmd->callback([a, exit_code]() { *exit_code = run_info(*a); });
}

}  // namespace spinhash::cli
