#include "flags/build_flags.hpp"

#include <map>
#include <string>

#include "calib/calibration_scans.hpp"
#include "spinhash/blob_format.hpp"
#include "spinhash/limits.hpp"

namespace spinhash::flags {
namespace {

// The calibration flags (pipeline::CalibrationSettings).
void add_calibration_flags(CLI::App* cmd, pipeline::CalibrationSettings* c) {
  cmd->add_flag("!--no-calibration", c->enabled,
                "skip the calibration scans: the recognizer's priors decide every level's flag (quick test "
                "databases)");
  cmd->add_option("--target-precision", c->fit.target_precision,
                  "precision each level's flag is fitted to on the calibration runs")
      ->check(CLI::Range(0.5, 1.0))
      ->capture_default_str();
  cmd->add_option("--agree-precision", c->fit.agree_precision,
                  "precision the cascade's stop is fitted to: the share of the queries the first pass "
                  "answers on which stopping loses no right answer (the full pass names the truth only "
                  "where the first pass does too)")
      ->check(CLI::Range(0.5, 1.0))
      ->capture_default_str();
  cmd->add_option(
         "--calibration-scans", c->runs.scans_per_model,
         "calibration scans per model (0: 32 up to 64 models, 2048 / models above, at least 2); a model "
         "left out gets more, up to 32, so that the left-out models give about 2048 runs")
      ->check(CLI::Range(0u, 1000u))
      ->capture_default_str();
  cmd->add_option(
         "--calibration-left-out-scans", c->runs.left_out_scans,
         "calibration scans of each model left out (0: as many as --calibration-scans, more up to 32 so "
         "that the left-out models give about 2048 runs)")
      ->check(CLI::Range(0u, 1000u))
      ->capture_default_str();
  cmd->add_option("--calibration-max-left-out", c->runs.max_left_out,
                  "models also recognised with a database built without them (a class-stratified sample when "
                  "there are more)")
      ->check(CLI::Range(0u, kMaxModels))
      ->capture_default_str();
  std::map<std::string, uint32_t> clutter;
  for (const uint32_t c : {blob::kClutterTiles, blob::kClutterVehicleSized})
    clutter[calib::calibration_clutter_word(c)] = c;
  cmd->add_option("--calibration-clutter", c->runs.clutter,
                  "clutter the flags are fitted against: tiles (trees, walls, crates, buildings) or "
                  "vehicle-sized (also sheds, freight containers, bushes and heaps: far fewer flags on "
                  "those, and on vehicles, most of all at the group level of sparse scans)")
      ->transform(CLI::CheckedTransformer(clutter, CLI::ignore_case))
      ->default_str(calib::calibration_clutter_word(blob::kClutterTiles));
  cmd->add_option("--calibration-seed", c->runs.seed, "seed of the calibration scans")->capture_default_str();
  cmd->add_option("--jobs", c->runs.jobs, "threads of the calibration (0: every hardware thread)")
      ->check(CLI::Range(0u, 1024u))
      ->capture_default_str();
}

}  // namespace

void add_build_flags(CLI::App* cmd, pipeline::BuildSettings* s) {
  FeatureParams& f = s->options.features;
  cmd->add_option("--radius", f.support_radius, "spin image support radius R, m")->capture_default_str();
  cmd->add_option("--bins", f.bins_alpha, "spin image bins per axis (bins x bins)")
      ->check(CLI::Range(1u, kMaxSpinBinsPerAxis))
      ->each([f_ptr = &f](const std::string&) { f_ptr->bins_beta = f_ptr->bins_alpha; })
      ->capture_default_str();
  cmd->add_option("--support-angle", f.support_angle_deg, "support angle, degrees (>= 180: off)")
      ->capture_default_str();
  cmd->add_option("--voxel", f.cloud_voxel, "density-equalising voxel, m")->capture_default_str();
  cmd->add_option("--normal-radius", f.normal_radius, "PCA normal radius, m")->capture_default_str();
  cmd->add_option("--basis-spacing", f.basis_spacing, "basis point spacing, m")->capture_default_str();
  cmd->add_option("--lsh-tables", s->options.lsh_tables, "L, LSH tables")
      ->check(CLI::Range(1u, kMaxLshTables))
      ->capture_default_str();
  cmd->add_option("--lsh-bits", s->options.lsh_bits, "K, bits per LSH key")
      ->check(CLI::Range(1u, kMaxLshBits))
      ->capture_default_str();
  cmd->add_option("--grid-cell", s->options.grid_cell, "cell of the per-model feature grids, m")
      ->check(CLI::Range(0.05, 10.0))
      ->capture_default_str();
  cmd->add_option("--field-cell", s->options.field.cell,
                  "voxel of the nearest-feature field, m (0: no field; a smaller blob, slower verification)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--field-reach", s->options.field.reach,
                  "the largest Delta_max the field answers for, m (a larger one searches the grid)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--field-slots", s->options.field.slots, "model features per field voxel")
      ->check(CLI::Range(1u, kMaxFieldSlots))
      ->capture_default_str();
  cmd->add_option("--lsh-range-quantile", s->options.lsh_range_quantile,
                  "quantile of each dimension used as its LSH range C_i")
      ->check(CLI::Range(0.5, 1.0))
      ->capture_default_str();
  cmd->add_option("--seed", s->options.seed, "LSH sampling seed")->capture_default_str();
  cmd->add_option("--scan-spacing", s->scan_spacing, "model scan ray spacing at the object, m")
      ->check(CLI::Range(0.005, 1.0))
      ->capture_default_str();
  std::map<std::string, host::ByteOrder> orders{{"native", host::ByteOrder::kNative},
                                                {"little", host::ByteOrder::kLittle},
                                                {"big", host::ByteOrder::kBig}};
  cmd->add_option("--byte-order", s->byte_order, "byte order of the target that reads the blob")
      ->transform(CLI::CheckedTransformer(orders, CLI::ignore_case));
  cmd->add_option(
         "--classes", s->class_manifest,
         "manifest of 'MODEL_NAME CLASS [GROUP]' lines (GROUP only for a class in no group: "
         "'buggy other light'); without it a model's class is its folder's name or "
         "its name's first word when that is a class (pickup/x.obj, sedan-03.obj), else unclassified")
      ->check(CLI::ExistingFile);
  add_calibration_flags(cmd, &s->calibration);
  cmd->add_flag("--quiet", s->quiet, "no progress on stderr");
}

}  // namespace spinhash::flags
