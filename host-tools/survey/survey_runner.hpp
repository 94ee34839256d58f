// A survey from start to end: prepare (catalogue, CRS check, plan, what a
// resumed run has done), run the tasks (the CLI: --jobs threads sharing one
// read-only database; Python: one Dask task each), store each result
// atomically as it comes, and finish (the outputs, from the stored results).
#pragma once
#include <string>
#include <vector>

#include "pipeline/tile_stream_order.hpp"
#include "spinhash/scene.hpp"
#include "survey/catalogue.hpp"
#include "survey/survey_outputs.hpp"
#include "survey/task.hpp"
#include "survey/tile_result.hpp"

namespace spinhash::survey {

struct SurveyOptions {
  std::string db_path, out_dir;
  unsigned jobs = 0;  // 0: every core
  double buffer = kDefaultBuffer;
  bool resume = false;
  bool quiet = false;        // no progress line
  host::WorkCrs work;        // --work-crs: the CRS to work in (else the tiles' shared CRS)
  host::PointFilter filter;  // --drop-class: classes left out besides noise
  SceneConfig scene;
  size_t order_memory_points = pipeline::kOrderMemoryPoints;  // --order-memory: each tile's order
};

// The scene settings of a survey (as `spinhash scene`'s defaults).
SceneConfig default_survey_scene();

struct PreparedSurvey {
  SurveyOptions options;
  Catalogue catalogue;
  std::vector<SurveyTask> tasks;  // path order
  std::vector<bool> done;         // per task: a stored result with the same key (--resume)
  std::vector<Refusal> refused;   // headers that could not be read
};

// False with *error: arguments naming nothing, tiles that do not share a
// CRS or a name, an output folder that cannot be made. Without resume, the
// stored results (tile-results/*.result) are removed: a fresh run.
bool prepare_survey(const SurveyOptions& options, const std::vector<std::string>& args, PreparedSurvey* out,
                    std::string* error);

// Where each tile's result is stored in the output folder: NAME.result.
constexpr const char* kResultsFolder = "tile-results";

// tile-results/NAME.result in the output folder, written atomically.
std::string result_path(const std::string& out_dir, const std::string& tile_name);
bool store_result(const std::string& out_dir, const TileResult& result, std::string* error);

// Reads back the stored results of the plan, writes the outputs and the
// manifest. failed: tasks that threw. Returns the exit status (0 every tile
// done and ok, 3 some refused, failed or not ok, 1 an output not written).
int finish_survey(const PreparedSurvey& survey, const std::vector<Refusal>& failed, double wall_s,
                  std::string* error);

// The CLI's survey: prepare, tasks on options.jobs threads, finish.
int run_survey(const SurveyOptions& options, const std::vector<std::string>& args);

}  // namespace spinhash::survey
