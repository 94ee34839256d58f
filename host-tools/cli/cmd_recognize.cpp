// spinhash recognize --db DB.shdb [--mode bran|sran|sind] [--top N]
//                    [--overlay-out F.ply] [--picture-out F.png] QUERY...
// One JSON object per query per line on stdout; progress and errors on stderr.
#include <cctype>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cli/json_line.hpp"
#include "cli/result_json.hpp"
#include "cloud/metric_source.hpp"
#include "flags/recognizer_flags.hpp"
#include "pipeline/answer_overlay.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/json_line.hpp"
#include "pipeline/object_units.hpp"
#include "pipeline/recognition_session.hpp"

namespace spinhash::cli {

using flags::add_recognizer_flags;
using pipeline::DatabaseFile;
using pipeline::load_database;
using pipeline::RecognitionSession;
namespace {

struct RecognizeArgs {
  std::string db_path;
  std::vector<std::string> queries;
  uint32_t top = 0;          // 0: every model that got a score
  std::string overlay_out;   // FILE.ply: the query and the posed model, coloured
  std::string picture_out;   // FILE.png: the same, top-down and side-on
  host::WorkCrs work;        // --work-crs: the CRS to work in (else each file's own)
  host::PointFilter filter;  // --drop-class: classes left out besides noise
  RecognizerConfig config;
};

// The query in metres of the CRS worked in, through the reading door
// (cloud/metric_source.hpp), which opens the file once; notes on stderr.
std::vector<double> read_query(const RecognizeArgs& a, const std::string& path, host::Crs* crs,
                               host::AxisUnits* units) {
  std::unique_ptr<host::MetricSource> source = host::open_metric_source(path, a.work, a.filter);
  const host::ToMetres& to_metres = source->to_metres();
  for (const std::string& note : to_metres.notes())
    std::fprintf(stderr, "spinhash recognize: %s: %s\n", host::cloud_name(path).c_str(), note.c_str());
  *crs = to_metres.work_crs();
  *units = to_metres.units();
  std::vector<double> xyz = host::read_all_points(*source);
  const std::string noise = host::dropped_note(source->points_noise(), a.filter);
  if (!noise.empty())
    std::fprintf(stderr, "spinhash recognize: %s: %s\n", host::cloud_name(path).c_str(), noise.c_str());
  return xyz;
}

// FILE.ext for one query; FILE-NAME.ext for each of several.
std::string output_for(const std::string& file, const std::string& query_name, size_t queries) {
  if (queries == 1) return file;
  const std::filesystem::path p(file);
  return (p.parent_path() / (p.stem().string() + "-" + query_name + p.extension().string())).string();
}

// The overlay and picture of one answer, when asked for; false with *error.
bool write_answer_views(const RecognizeArgs& a, const std::string& name, const Database& db,
                        const std::vector<double>& xyz, const Result& r, std::string* error) {
  if (a.overlay_out.empty() && a.picture_out.empty()) return true;
  const pipeline::AnswerOverlay o = pipeline::make_answer_overlay(db, xyz, r);
  if (o.model.empty())
    std::fprintf(stderr,
                 "spinhash recognize: %s: no posed model to show; the overlay holds the query alone\n",
                 name.c_str());
  const size_t n = a.queries.size();
  return (a.overlay_out.empty() ||
          pipeline::write_overlay_ply(output_for(a.overlay_out, name, n), o, error)) &&
         (a.picture_out.empty() ||
          pipeline::write_overlay_picture(output_for(a.picture_out, name, n), name, o, error));
}

// A CLI11 check that a file name ends in `extension` (any case).
CLI::Validator extension_check(const std::string& extension) {
  return CLI::Validator(
      [extension](std::string& path) {
        std::string ext = std::filesystem::path(path).extension().string();
        for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        return ext == extension ? std::string() : "must end in " + extension + ": " + path;
      },
      "FILE" + extension);
}

int run_recognize(const RecognizeArgs& a) {
  DatabaseFile file;
  RecognitionSession session;
  std::string error;
  if (!load_database(a.db_path, &file, &error) || !session.init(&file.db, a.config, &error)) {
    std::fprintf(stderr, "spinhash recognize: %s\n", error.c_str());
    return kExitError;
  }
  int exit_code = kExitOk;
  for (const std::string& q : a.queries) {
    const std::string name = host::cloud_name(q);
    std::vector<double> xyz;
    host::Crs crs;
    host::AxisUnits units;
    try {
      xyz = read_query(a, q, &crs, &units);
    } catch (const std::exception& e) {
      // An unreadable file still gets its line, so readers can pair lines with queries.
      std::printf("%s\n", pipeline::unreadable_json("query", name, e.what()).c_str());
      std::fflush(stdout);
      std::fprintf(stderr, "spinhash recognize: %s\n", e.what());  // the reader names the file
      exit_code = kExitCheckFailed;
      continue;
    }
    Result r = session.recognize(xyz);
    std::vector<RankedModel> ranking;
    const Result out = pipeline::in_file_units(r, units, &ranking);
    std::printf(
        "%s\n",
        result_json(name, file.db, out, a.top, session.last_ms(), crs.known() ? crs.describe() : "").c_str());
    std::fflush(stdout);  // a line per query as soon as it is known
    if (r.status != Status::kOk) exit_code = kExitCheckFailed;
    if (!write_answer_views(a, name, file.db, xyz, r, &error)) {
      std::fprintf(stderr, "spinhash recognize: %s\n", error.c_str());
      exit_code = kExitError;
    }
  }
  return exit_code;
}

}  // namespace

void add_recognize_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<RecognizeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "recognize",
      "recognise point clouds (LAS, LAZ, COPC, PLY or x y z text; '-': stdin) against a database");
  cmd->add_option("--db", a->db_path, "database file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--top", a->top, "models listed per query (default: all that got a score)");
  cmd->add_option(
         "--overlay-out", a->overlay_out,
         "PLY of the query (grey-blue) and the best model's points in its pose (orange), georeferenced; "
         "several queries: FILE-NAME.ply each")
      ->check(extension_check(".ply"));
  cmd->add_option("--picture-out", a->picture_out,
                  "PNG of the same, top-down and side-on, titled with the model and its confidence; "
                  "several queries: FILE-NAME.png each")
      ->check(extension_check(".png"));
  add_work_crs_option(cmd, &a->work);
  add_drop_class_option(cmd, &a->filter);
  cmd->add_option("queries", a->queries, "point cloud files ('-': stdin)")->required();
  add_recognizer_flags(cmd, &a->config);
  cmd->callback([a, exit_code]() {
    refuse_repeated_stdin(a->queries);
    *exit_code = run_recognize(*a);
  });
}

}  // namespace spinhash::cli
