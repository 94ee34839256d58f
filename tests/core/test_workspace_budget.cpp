// Workspace threshold test (onboard rule 3, docs/onboard-rules.md, as TFLM's arena threshold tests):
// required_workspace_bytes() for the default config and for a 20 000-point
// query may not change unnoticed. If a change moves them on purpose, copy the
// new values from the failure message into the constants below and into
// docs/budgets.md ("Workspace"), and say why in the commit message.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>

#include "spinhash/recognizer.hpp"
#include "spinhash/scene.hpp"
#include "spinhash/scene_stream.hpp"

using namespace spinhash;

namespace {

struct WorkspaceThreshold {
  size_t default_config;  // RecognizerConfig{}
  size_t points_20000;    // RecognizerConfig{} with max_points = 20000
  size_t scene_300000;    // SceneConfig{}: 300 000-point windows, their grids, a default recognizer and
                          // the stream's buffer the tile API sizes from them (scene_tile.hpp)
  size_t stream_1m;       // StreamConfig{}: windows of 300 000 points, 1 M points buffered
};
// Pointer-sized members make 64-bit layouts larger than 32-bit ones, and a
// SceneObject's 8-byte aligned statistics pad differently on 32-bit ABIs.
// The scene's figures hold a recognizer (its config and workspace) and 256
// SceneObjects, each with its class ranking and its recognition's
// statistics, so a statistic or a stage parameter moves them.
constexpr WorkspaceThreshold kThreshold64 = {6455104, 5625184, 53505872, 45292808};
constexpr WorkspaceThreshold kThreshold32 = {6454912, 5624992, 53503904, 45290872};
// Padding and alignment may move a few bytes between ABIs of one pointer size
// (armhf and powerpc agree today); anything larger is a real change.
constexpr size_t kToleranceBytes = 1024;

constexpr WorkspaceThreshold kThreshold = sizeof(void*) == 8 ? kThreshold64 : kThreshold32;

void check_close(size_t measured, size_t recorded) {
  CHECK_MESSAGE(measured <= recorded + kToleranceBytes, "workspace grew to ", measured, " bytes (recorded ",
                recorded, ")");
  CHECK_MESSAGE(measured + kToleranceBytes >= recorded, "workspace shrank to ", measured, " bytes (recorded ",
                recorded, "): update the threshold");
}

}  // namespace

TEST_CASE("workspace: the default config needs the recorded number of bytes") {
  CAPTURE(sizeof(void*));
  check_close(required_workspace_bytes(RecognizerConfig{}), kThreshold.default_config);
}

TEST_CASE("workspace: a 20 000-point query needs the recorded number of bytes") {
  RecognizerConfig cfg;
  cfg.max_points = 20000;
  CAPTURE(sizeof(void*));
  check_close(required_workspace_bytes(cfg), kThreshold.points_20000);
}

TEST_CASE("workspace: a 300 000-point scene tile needs the recorded number of bytes") {
  SceneConfig cfg;
  cfg.max_tile_points = 300000;
  CAPTURE(sizeof(void*));
  check_close(required_scene_workspace_bytes(cfg), kThreshold.scene_300000);
}

TEST_CASE("workspace: a stream of 300 000-point windows and 1 M buffered points needs the recorded bytes") {
  StreamConfig cfg;
  cfg.scene.max_tile_points = 300000;
  cfg.max_buffered_points = 1000000;
  CAPTURE(sizeof(void*));
  check_close(required_stream_workspace_bytes(cfg), kThreshold.stream_1m);
}
