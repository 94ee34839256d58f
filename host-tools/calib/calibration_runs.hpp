// The calibration runs of `spinhash build`: every model scanned
// scans_per_model times (calibration_scans.hpp) and recognised with the
// database as built (known); a class-stratified sample of at most
// max_left_out models recognised from the same scans again with a database
// built without them (unknown: leave-one-model-out, derived from the full
// content, db/leave_one_out.hpp); and scans of clutter. Every recognition
// records its density and each level's evidence and rightness
// (db/calibration_fit.hpp), once for each calibrated pass: the full pass
// (the recognizer's settings, the cascade off) and the cascade's first pass
// (its first_* settings) recognise every scan, and the pair gives the
// agree record (agree_record()). On all threads, the runs in a fixed order
// whatever their number.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "blob/blob_content.hpp"
#include "db/calibration_fit.hpp"
#include "mesh/mesh.hpp"
#include "spinhash/config.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash::calib {

struct RunSettings {
  // Scans of each model, recognised with the database as built; 0:
  // default_scans_per_model(). A model left out is scanned at least as
  // often, and often enough that the unknown runs reach about
  // kUnknownRunsWanted (left_out_scans()); its first scans_per_model scans
  // are also recognised with it in.
  uint32_t scans_per_model = 0;
  uint32_t left_out_scans = 0;  // scans of each model left out; 0: left_out_scans()
  uint32_t max_left_out = 64;   // models recognised left out (all of them when there are fewer)
  uint32_t clutter_scans = 0;   // 0: default_clutter_scans()
  // The kinds of clutter scanned (blob::CalibrationClutter): vehicle-sized
  // clutter holds the vehicle levels' flags off sheds, containers, bushes
  // and heaps, and costs them many right answers (docs/decisions/017).
  uint32_t clutter = blob::kClutterTiles;
  uint64_t seed = 1;            // of every draw
  uint32_t jobs = 0;            // threads; 0: every hardware thread
  RecognizerConfig recognizer;  // the passes' settings: the full pass's, and first_* the first pass's
  bool quiet = false;           // no progress on stderr
};

// Runs the fit wants of the known and of the unknown vehicles: about 100
// per band of density for each of them at a 0.99 target, over six bands,
// three times over.
constexpr uint32_t kKnownRunsWanted = 2048;
constexpr uint32_t kUnknownRunsWanted = 2048;
// Scans per model when none is asked for: 32 up to 64 models, fewer above
// (at least 2), so that the known runs stay about kKnownRunsWanted.
uint32_t default_scans_per_model(uint32_t models);
// Scans of each model left out: scans_per_model, or more (at most 32) so
// that the left-out models give about kUnknownRunsWanted runs.
uint32_t left_out_scans(uint32_t scans_per_model, uint32_t left_out);
// Clutter scans when none is asked for: an eighth of the unknown runs, 32
// to 256, spread over the kinds asked for.
uint32_t default_clutter_scans(uint32_t unknown_runs);

// The models left out: all when they are at most `max`, else `max` of them
// spread over the classes in proportion to their members (each class with
// at least one, while `max` allows), evenly through each class's models.
std::vector<uint32_t> left_out_models(const std::vector<blob::ModelRecord>& models, uint32_t max);

// Which levels of `r` name the truth: a vehicle (every vehicle scan), its
// group (the model's own where it has one: vehicle_group_of(class, own)),
// its class, its model (`model` < 0: not in the database). `clutter`:
// nothing is right.
void judge(const Result& r, bool clutter, int64_t model, uint32_t vehicle_class, uint32_t group,
           bool right[kCalibratedLevels]);

// The agree pass's record of one scan: the first pass's density and
// evidence; wrong at a level only when stopping there would lose a right
// answer: the full pass names the truth at that level (judge()) and the
// first pass does not. Where both are right, both wrong, or only the first
// is right, the stop loses nothing.
host::CalibrationRun agree_record(host::RunKind kind, const Result& first, const Result& full, int64_t model,
                                  uint32_t vehicle_class, uint32_t group);

struct RunSummary {
  host::FitProvenance drawn;  // scans per model, models left out, ..., seed
  uint32_t jobs = 0;
  double seconds = 0.0;
};

// `meshes[i]` is model i of `full` (its name). false with *error when a
// scan or a database fails.
bool run_calibration(const host::BlobContent& full, const std::vector<const host::Mesh*>& meshes,
                     const RunSettings& settings, std::vector<host::CalibrationRun>* runs,
                     RunSummary* summary, std::string* error);

}  // namespace spinhash::calib
