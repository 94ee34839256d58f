// spinhash survey --db DB.shdb --out DIR [--jobs N] [--buffer M] [--resume] TILE... | DIR
// Every vehicle of a survey of adjacent tiles, each tile read with its
// neighbours' buffer and reporting the objects it owns, on --jobs threads;
// detections.jsonl, detections.geojson, detections.gpkg and survey.json in
// DIR (host-tools/survey/, docs/survey.md).
#include <memory>

#include "cli/commands.hpp"
#include "flags/recognizer_flags.hpp"
#include "flags/scene_flags.hpp"
#include "survey/survey_runner.hpp"

namespace spinhash::cli {

void add_survey_command(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<survey::SurveyOptions>();
  auto tiles = std::make_shared<std::vector<std::string>>();
  o->scene = survey::default_survey_scene();
  CLI::App* cmd = app.add_subcommand(
      "survey",
      "every vehicle of a survey of adjacent tiles, on all cores, with GIS outputs (docs/survey.md)");
  cmd->add_option("--db", o->db_path, "database file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", o->out_dir, "output folder (made if missing)")->required();
  cmd->add_option("--jobs", o->jobs, "tiles processed at once (default: every core)")
      ->check(CLI::Range(1u, 1024u));
  cmd->add_option("--buffer", o->buffer,
                  "m of the neighbours' points read around each tile (default 40: half the longest vehicle + "
                  "the terrain filter's reach)")
      ->check(CLI::Range(survey::kMinBuffer, survey::kMaxBuffer));
  cmd->add_flag("--resume", o->resume, "keep the tiles a previous run in DIR finished (same inputs)");
  cmd->add_flag("--quiet", o->quiet, "no progress line");
  add_work_crs_option(cmd, &o->work);
  add_drop_class_option(cmd, &o->filter);
  add_order_memory_option(cmd, &o->order_memory_points);
  flags::add_scene_flags(cmd, &o->scene, {"--top", "--max-objects"});
  flags::add_set_option(cmd, &o->scene.recognizer);  // --preset, --set STAGE.FIELD=VALUE
  cmd->add_option("tiles", *tiles, "tiles (LAS, LAZ, COPC, PLY, x y z text) or folders of them")
      ->required()
      ->check(CLI::ExistingPath);  // planned before any runs: a missing one is a usage error
  cmd->callback([o, tiles, exit_code]() { *exit_code = survey::run_survey(*o, *tiles); });
}

}  // namespace spinhash::cli
