// spinhash recognize --db DB.shdb [--mode bran|sran|sind] [--top N] QUERY...
// One JSON object per query per line on stdout; progress and errors on stderr.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cli/json_line.hpp"
#include "cli/result_json.hpp"
#include "cloud/cloud_reader.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/recognizer_flags.hpp"

namespace spinhash::cli {

using pipeline::add_recognizer_flags;
using pipeline::DatabaseFile;
using pipeline::load_database;
using pipeline::RecognitionSession;
namespace {

struct RecognizeArgs {
  std::string db_path;
  std::vector<std::string> queries;
  uint32_t top = 0;  // 0: every model that got a score
  RecognizerConfig config;
};

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
    if (!host::read_cloud(q, &xyz, &error)) {
      // An unreadable file still gets its line, so readers can pair lines with queries.
      std::printf("{\"query\":%s,\"status\":\"unreadable\",\"error\":%s,\"ranking\":[],\"pose\":null,%s}\n",
                  json_string(name).c_str(), json_string(error).c_str(), json_version_member().c_str());
      std::fprintf(stderr, "spinhash recognize: %s\n", error.c_str());  // the reader names the file
      exit_code = kExitCheckFailed;
      continue;
    }
    Result r = session.recognize(xyz);
    std::printf("%s\n", result_json(name, file.db, r, a.top, session.last_ms()).c_str());
    std::fflush(stdout);  // a line per query as soon as it is known
    if (r.status != Status::kOk) exit_code = kExitCheckFailed;
  }
  return exit_code;
}

}  // namespace

void add_recognize_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<RecognizeArgs>();
  CLI::App* cmd =
      app.add_subcommand("recognize", "recognise point clouds (PLY or x y z text) against a database");
  cmd->add_option("--db", a->db_path, "database file")->required();
  cmd->add_option("--top", a->top, "models listed per query (default: all that got a score)");
  cmd->add_option("queries", a->queries, "point cloud files ('-': stdin)")->required();
  add_recognizer_flags(cmd, &a->config);
  cmd->callback([a, exit_code]() {
    refuse_repeated_stdin(a->queries);
    *exit_code = run_recognize(*a);
  });
}

}  // namespace spinhash::cli
