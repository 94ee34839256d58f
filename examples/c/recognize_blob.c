/* Recognises one point cloud against a spinhash database through the C99 API,
 * the way C firmware would: static buffers only, no heap.
 *
 *   recognize_blob DB.shdb CLOUD.i16 [EXPECTED_TOP_MODEL]
 *
 * CLOUD.i16 holds x y z triples of little-endian int16 millimetres (the
 * format of tests/golden/golden_query0.i16). With a third argument
 * the program fails unless that model is ranked first (used by CI). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "spinhash/spinhash.h"

enum {
  kMaxBlobBytes = 1 << 20,  /* flash image budget of this example */
  kMaxPoints = 8192,        /* sensor frame capacity */
  kWorkspaceBytes = 6 << 20 /* >= spinhash_workspace_bytes() for the config below */
};

/* 64-byte alignment without C11: over-allocate and round the address up. */
static unsigned char blob_storage[kMaxBlobBytes + SPINHASH_BUFFER_ALIGNMENT];
static unsigned char workspace_storage[kWorkspaceBytes + SPINHASH_BUFFER_ALIGNMENT];
static float cloud[3 * kMaxPoints];
static spinhash_database database;
static spinhash_recognizer recognizer;

static unsigned char* aligned(unsigned char* p) {
  uintptr_t a = (uintptr_t)p;
  return p + ((SPINHASH_BUFFER_ALIGNMENT - a % SPINHASH_BUFFER_ALIGNMENT) % SPINHASH_BUFFER_ALIGNMENT);
}

static void log_to_stderr(int level, const char* message) {
  fprintf(stderr, "spinhash[%d]: %s\n", level, message);
}

/* Reads at most max bytes; returns the count, or 0 on error or overflow. */
static size_t read_file(const char* path, unsigned char* out, size_t max) {
  size_t n;
  FILE* f = fopen(path, "rb");
  if (f == NULL) return 0;
  n = fread(out, 1, max, f);
  if (n == max && fgetc(f) != EOF) n = 0; /* larger than the buffer */
  fclose(f);
  return n;
}

/* The file is little-endian; decode bytewise so big-endian targets work too. */
static uint32_t load_cloud(const char* path) {
  static unsigned char raw[3 * kMaxPoints * 2];
  size_t n = read_file(path, raw, sizeof raw), i;
  for (i = 0; i + 2 <= n; i += 2) {
    int16_t mm = (int16_t)(uint16_t)(raw[i] | raw[i + 1] << 8);
    cloud[i / 2] = (float)mm * 0.001f;
  }
  return (uint32_t)(n / 6);
}

int main(int argc, char** argv) {
  spinhash_config config;
  spinhash_result result;
  spinhash_ranked_model entry;
  unsigned char* blob = aligned(blob_storage);
  size_t blob_bytes, need;
  uint32_t points, i;
  spinhash_status s;

  if (argc < 3) {
    fprintf(stderr, "usage: %s DB.shdb CLOUD.i16 [EXPECTED_TOP_MODEL]\n", argv[0]);
    return 2;
  }
  spinhash_set_log_hook(log_to_stderr);
  blob_bytes = read_file(argv[1], blob, kMaxBlobBytes);
  points = load_cloud(argv[2]);
  s = spinhash_database_open(&database, blob, blob_bytes);
  if (s != SPINHASH_OK) return 1; /* the hook has said why */

  spinhash_default_config(&config);
  config.seed = 7;
  config.max_points = kMaxPoints;
  config.max_models = 16;
  config.draws.max_hypotheses = 2000; /* the frame-time budget: stop early, best answer so far */
  need = spinhash_workspace_bytes(&config);
  printf("database: %u models, %lu bytes; workspace %lu bytes; cloud %u points\n",
         (unsigned)spinhash_database_model_count(&database), (unsigned long)blob_bytes, (unsigned long)need,
         (unsigned)points);
  if (need == 0 || need > kWorkspaceBytes) return 1;
  s = spinhash_recognizer_init(&recognizer, &database, &config, aligned(workspace_storage), kWorkspaceBytes);
  if (s != SPINHASH_OK) return 1;

  s = spinhash_recognize_f32(&recognizer, cloud, points, &result);
  printf("status %s, %u ranked, confident %u, %u features, %u hypotheses, budget exhausted %u\n",
         spinhash_status_name(s), (unsigned)result.ranking_count, (unsigned)result.confident,
         (unsigned)result.stats.features, (unsigned)result.stats.hypotheses,
         (unsigned)result.stats.budget_exhausted);
  if (s != SPINHASH_OK || result.ranking_count == 0) return 1;
  for (i = 0; i < result.ranking_count && i < 3; ++i) {
    if (spinhash_result_entry(&result, i, &entry) != SPINHASH_OK) return 1;
    printf("  #%u %-8s score %10.3f  t = (%.3f, %.3f, %.3f)\n", (unsigned)(i + 1), entry.name,
           (double)entry.score, entry.pose[3], entry.pose[7], entry.pose[11]);
  }
  spinhash_result_entry(&result, 0, &entry);
  if (argc > 3 && strcmp(entry.name, argv[3]) != 0) {
    fprintf(stderr, "expected %s first, got %s\n", argv[3], entry.name);
    return 1;
  }
  return 0;
}
