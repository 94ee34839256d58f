/* Bare-metal main: the golden blob in flash, a static workspace in RAM, one
 * recognition of a synthetic box-shaped cloud. Built to prove that the core
 * links without an OS or heap and to measure code and data size; the result
 * goes to volatile globals that a debugger (or a test rig) would read. */
#include <stddef.h>
#include <stdint.h>

#include "spinhash/spinhash.h"

enum {
  kMaxPoints = 4096, /* sensor frame capacity */
  kMaxFeatures = 256,
  kMaxModels = 16,
  kSpinDims = 100, /* 10 x 10 bins, as the golden blob */
  kWorkspaceBytes =
      1 << 20, /* >= spinhash_workspace_bytes() of this config (checked): 0.87 MB on 64-bit hosts */
  kSide = 20   /* grid steps along each edge of the synthetic box's faces */
};

extern const unsigned char spinhash_blob[];
extern const size_t spinhash_blob_size;

static unsigned char workspace[kWorkspaceBytes] __attribute__((aligned(SPINHASH_BUFFER_ALIGNMENT)));
static float cloud[3 * kMaxPoints];
static spinhash_database database;
static spinhash_recognizer recognizer;

volatile int32_t g_status = -1;
volatile uint32_t g_best_model = 0xFFFFFFFFu;
volatile float g_best_score = 0.0f;
volatile uint32_t g_budget_exhausted = 0;

/* Top and two sides of a 4.5 x 1.8 x 0.9 m box: what an airborne sensor sees of a car hull. */
static uint32_t make_box_view(void) {
  const float sx = 4.5f, sy = 1.8f, sz = 0.9f;
  uint32_t n = 0, i, j;
  for (i = 0; i <= kSide; ++i)
    for (j = 0; j <= kSide; ++j) {
      const float u = (float)i / (float)kSide, v = (float)j / (float)kSide;
      const float top[3] = {(u - 0.5f) * sx, (v - 0.5f) * sy, sz};
      const float side[3] = {(u - 0.5f) * sx, -0.5f * sy, v * sz};
      const float front[3] = {0.5f * sx, (u - 0.5f) * sy, v * sz};
      const float* p[3] = {top, side, front};
      int k, a;
      for (k = 0; k < 3; ++k)
        for (a = 0; a < 3; ++a) cloud[3 * n + 3 * (uint32_t)k + (uint32_t)a] = p[k][a];
      n += 3;
    }
  return n;
}

int main(void) {
  spinhash_config config;
  spinhash_result result;
  spinhash_ranked_model best;
  uint32_t points;

  g_status = spinhash_database_open(&database, spinhash_blob, spinhash_blob_size);
  if (g_status != SPINHASH_OK) return 1;
  spinhash_default_config(&config);
  config.max_points = kMaxPoints;
  config.max_features = kMaxFeatures;
  config.max_models = kMaxModels;
  config.max_spin_dims = kSpinDims;
  if (spinhash_workspace_bytes(&config) > sizeof workspace) return 2;
  g_status = spinhash_recognizer_init(&recognizer, &database, &config, workspace, sizeof workspace);
  if (g_status != SPINHASH_OK) return 3;
  points = make_box_view();
  g_status = spinhash_recognize_f32(&recognizer, cloud, points, &result);
  if (g_status != SPINHASH_OK || spinhash_result_entry(&result, 0, &best) != SPINHASH_OK) return 4;
  g_best_model = best.model;
  g_best_score = best.score;
  g_budget_exhausted = result.stats.budget_exhausted;
  return 0;
}
