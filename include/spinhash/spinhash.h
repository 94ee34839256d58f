/* spinhash C99 API: the onboard core for C firmware.
 *
 * No heap, no exceptions: the caller owns every byte. A database view and a
 * recognizer live in opaque storage objects declared by the caller (static,
 * stack or a struct member); the workspace is a caller buffer aligned to
 * SPINHASH_BUFFER_ALIGNMENT of spinhash_workspace_bytes(config) bytes; the
 * blob stays where it is (flash, mmap, const array) for as long as it is used.
 *
 * Typical use:
 *   static spinhash_database db;  static spinhash_recognizer rec;
 *   spinhash_config cfg;  spinhash_default_config(&cfg);
 *   spinhash_database_open(&db, blob, blob_size);
 *   spinhash_recognizer_init(&rec, &db, &cfg, workspace, workspace_size);
 *   spinhash_result res;  spinhash_recognize_f32(&rec, xyz, count, &res);
 *   for (i = 0; i < res.ranking_count; ++i) spinhash_result_entry(&res, i, &entry);
 *
 * Every function is safe to call with null pointers (it returns
 * SPINHASH_INVALID_ARGUMENT, 0 or a null name). Compiles as C99 and C++. */
#ifndef SPINHASH_SPINHASH_H
#define SPINHASH_SPINHASH_H

#include <stddef.h>
#include <stdint.h>

#include "spinhash/answer_levels.h"
#include "spinhash/config_fields.h"
#include "spinhash/stage_fields.h"
#include "spinhash/status_list.h"
#include "spinhash/vehicle_classes.h"

#ifdef __cplusplus
#define SPINHASH_NOEXCEPT noexcept /* the C++ side never throws */
extern "C" {
#else
#define SPINHASH_NOEXCEPT
#endif

/* Blob and workspace base addresses must be multiples of this. */
#define SPINHASH_BUFFER_ALIGNMENT 64

/* Opaque storage sizes, the same on every target (checked against the C++
 * objects by static_assert in firmware-lib/c_api/). */
#define SPINHASH_DATABASE_STORAGE_BYTES 128
#define SPINHASH_RECOGNIZER_STORAGE_BYTES 1024
#define SPINHASH_STORAGE_ALIGNMENT 8

/* Values mirror spinhash::Status (include/spinhash/status.hpp) exactly: both
 * are SPINHASH_STATUS_LIST (status_list.h), only ever appended to. */
#define SPINHASH_C_STATUS(cxx, value, c, word, message) SPINHASH_##c = value,
typedef enum spinhash_status { SPINHASH_STATUS_LIST(SPINHASH_C_STATUS) } spinhash_status;

typedef enum spinhash_mode {
  SPINHASH_MODE_BRAN = 0, /* batch RANSAC over the joint LSH index */
  SPINHASH_MODE_SRAN = 1, /* sequential per-model RANSAC (baseline) */
  SPINHASH_MODE_SIND = 2  /* spin-image indexing by votes, no geometry (baseline) */
} spinhash_mode;

/* Opaque, caller-owned: spinhash_database_open and spinhash_recognizer_init fill them. */
typedef union spinhash_database {
  unsigned char bytes[SPINHASH_DATABASE_STORAGE_BYTES];
  double align_double;
  uint64_t align_u64;
} spinhash_database;

typedef union spinhash_recognizer {
  unsigned char bytes[SPINHASH_RECOGNIZER_STORAGE_BYTES];
  double align_double;
  uint64_t align_u64;
} spinhash_recognizer;

/* Each stage's parameters: one struct per entry of SPINHASH_STAGES
 * (stage_fields.h), spinhash_<id>_params, one member per entry of its
 * SPINHASH_PARAMS_<id>, in that order (the list gives each one's default,
 * range and meaning). BOOL members are 0 or 1. */
#define SPINHASH_C_STAGE_STRUCT(id, Name, what)    \
  typedef struct spinhash_##id##_params {          \
    SPINHASH_PARAMS_##id(SPINHASH_C_PARAMS_MEMBER) \
  } spinhash_##id##_params;
SPINHASH_STAGES(SPINHASH_C_STAGE_STRUCT)
#undef SPINHASH_C_STAGE_STRUCT

/* Recognition settings: one member per entry of SPINHASH_CONFIG_FIELDS
 * (config_fields.h), in that order, then one per stage, named by its id
 * (cfg.draws.max_trials); see spinhash::RecognizerConfig (config.hpp) for
 * the meaning and default of the first. Start from
 * spinhash_default_config(). BOOL members are 0 or 1; mode is a
 * spinhash_mode. */
#define SPINHASH_C_STAGE_MEMBER(id, Name, what) spinhash_##id##_params id;
typedef struct spinhash_config {
  SPINHASH_CONFIG_FIELDS(SPINHASH_C_CONFIG_MEMBER)
  SPINHASH_STAGES(SPINHASH_C_STAGE_MEMBER)
} spinhash_config;
#undef SPINHASH_C_STAGE_MEMBER

/* What one recognition did: one member per entry of SPINHASH_STATS_FIELDS
 * (config_fields.h); see spinhash::RecognitionStats (recognizer.hpp). */
typedef struct spinhash_stats {
  SPINHASH_STATS_FIELDS(SPINHASH_C_STATS_MEMBER)
} spinhash_stats;

/* One recognition. The ranking it refers to lives in the recognizer's
 * workspace: valid until the next recognize call on that recognizer. */
typedef struct spinhash_result {
  int32_t status; /* spinhash_status */
  uint32_t ranking_count;
  uint32_t confident; /* 1: the best model explains enough of the query */
  /* Leading models within confidence.min_margin x sqrt(features) of the
   * first: the scan does not tell them apart (1: the first stands alone; 0:
   * no ranking). */
  uint32_t group_size;
  /* The classes of the ranked models, best first (spinhash_result_class),
   * and whether the first is confident: it leads the next class by
   * confidence.min_margin x sqrt(features) on enough evidence (docs/api.md). */
  uint32_t class_ranking_count;
  uint32_t class_confident;
  /* The answer levels (SPINHASH_ANSWER_LEVELS, answer_levels.h): per
   * calibrated level, vehicle .. model at index id - 1, its flag (the
   * database's calibrated threshold at the scan's density; the model
   * level's is `confident`, the class level's `class_confident`) and its
   * evidence (-infinity when a prerequisite of the level failed); `level`,
   * the id of the most specific confident level whose coarser levels are
   * confident and consistent (0: none; spinhash_level_name). The groups of
   * the ranked models, best first (spinhash_result_group). */
  uint32_t level_confident[SPINHASH_CALIBRATED_LEVELS];
  float level_evidence[SPINHASH_CALIBRATED_LEVELS];
  uint32_t level;
  uint32_t group_ranking_count;
  spinhash_stats stats;
  const void* ranking_;               /* private */
  const void* class_ranking_;         /* private */
  const void* group_ranking_;         /* private */
  const spinhash_database* database_; /* private: for model names */
} spinhash_result;

/* One ranked model. pose is row-major 4x4, model frame -> query frame (in
 * the input's coordinates, georeferenced included): x_q = R x_m + t. */
typedef struct spinhash_ranked_model {
  uint32_t model;    /* index into the database's model table */
  float score;       /* larger is better */
  uint32_t has_pose; /* 0 for SIND */
  uint32_t hypotheses;
  uint32_t inliers;
  double pose[16];
  const char* name; /* NUL-terminated, inside the blob */
} spinhash_ranked_model;

/* One ranked vehicle class: scored by its best model. */
typedef struct spinhash_ranked_class {
  uint32_t vehicle_class; /* id in SPINHASH_VEHICLE_CLASSES (vehicle_classes.h) */
  float score;            /* its best model's score */
  uint32_t model;         /* that model */
  const char* name;       /* the class's name, e.g. "pickup" */
} spinhash_ranked_class;

/* One ranked vehicle group: scored by its best model. */
typedef struct spinhash_ranked_group {
  uint32_t group;   /* id in SPINHASH_VEHICLE_GROUPS (vehicle_classes.h) */
  float score;      /* its best model's score */
  uint32_t model;   /* that model */
  const char* name; /* the group's name, e.g. "light" */
} spinhash_ranked_group;

/* Log levels passed to the hook. */
#define SPINHASH_LOG_ERROR 1
#define SPINHASH_LOG_WARNING 2
#define SPINHASH_LOG_INFO 3

/* One process-wide hook for the core's diagnostics (route it to a UART).
 * Null (the default) silences them. Built with SPINHASH_NO_LOG_STRINGS, the
 * core holds no message text and the hook receives "" with the level. */
typedef void (*spinhash_log_hook)(int level, const char* message);
void spinhash_set_log_hook(spinhash_log_hook hook) SPINHASH_NOEXCEPT;

/* Short English name of a status; "unknown" for values not listed. */
const char* spinhash_status_name(int32_t status) SPINHASH_NOEXCEPT;

/* Fills *config with the defaults (the paper's settings). */
void spinhash_default_config(spinhash_config* config) SPINHASH_NOEXCEPT;
/* Workspace bytes needed for *config; 0 if the config is invalid. */
size_t spinhash_workspace_bytes(const spinhash_config* config) SPINHASH_NOEXCEPT;

/* Validates the blob once (every offset, count and checksum) and fills *db. */
spinhash_status spinhash_database_open(spinhash_database* db, const void* bytes,
                                       size_t size) SPINHASH_NOEXCEPT;
uint32_t spinhash_database_model_count(const spinhash_database* db) SPINHASH_NOEXCEPT;
/* Name of model `index`, or a null pointer when out of range / not open. */
const char* spinhash_database_model_name(const spinhash_database* db, uint32_t index) SPINHASH_NOEXCEPT;

/* Vehicle class id of model `index` (vehicle_classes.h), or
 * SPINHASH_CLASS_COUNT when out of range / not open. */
uint32_t spinhash_database_model_class(const spinhash_database* db, uint32_t index) SPINHASH_NOEXCEPT;
/* Group id of model `index` (SPINHASH_VEHICLE_GROUPS): its class's, or its
 * own where its class is in no group and the build gave it one (an "other"
 * buggy in "light"); SPINHASH_GROUP_COUNT when out of range / not open. */
uint32_t spinhash_database_model_group(const spinhash_database* db, uint32_t index) SPINHASH_NOEXCEPT;
/* Name of class id `vehicle_class` ("sedan", ...); "unknown" outside the list. */
const char* spinhash_class_name(uint32_t vehicle_class) SPINHASH_NOEXCEPT;
/* Group id (SPINHASH_VEHICLE_GROUPS, vehicle_classes.h) of class id
 * `vehicle_class`: the class list's group column; 0 ("none") outside the list. */
uint32_t spinhash_class_group(uint32_t vehicle_class) SPINHASH_NOEXCEPT;
/* Name of group id `group` ("light", ...); "unknown" outside the list. */
const char* spinhash_group_name(uint32_t group) SPINHASH_NOEXCEPT;

/* Name of answer level id `level` ("none", "vehicle", "group", "class",
 * "model"; answer_levels.h); "unknown" outside the list. */
const char* spinhash_level_name(uint32_t level) SPINHASH_NOEXCEPT;

/* Carves every buffer from the workspace; the database must outlive rec. */
spinhash_status spinhash_recognizer_init(spinhash_recognizer* rec, const spinhash_database* db,
                                         const spinhash_config* config, void* workspace,
                                         size_t workspace_bytes) SPINHASH_NOEXCEPT;
/* xyz: count points as x y z triples. Returns result->status. */
spinhash_status spinhash_recognize_f32(spinhash_recognizer* rec, const float* xyz, uint32_t count,
                                       spinhash_result* result) SPINHASH_NOEXCEPT;
spinhash_status spinhash_recognize_f64(spinhash_recognizer* rec, const double* xyz, uint32_t count,
                                       spinhash_result* result) SPINHASH_NOEXCEPT;
/* Entry `rank` (0 = best) of a successful result. */
spinhash_status spinhash_result_entry(const spinhash_result* result, uint32_t rank,
                                      spinhash_ranked_model* out) SPINHASH_NOEXCEPT;
/* Class `rank` (0 = best) of a successful result. */
spinhash_status spinhash_result_class(const spinhash_result* result, uint32_t rank,
                                      spinhash_ranked_class* out) SPINHASH_NOEXCEPT;
/* Group `rank` (0 = best) of a successful result. */
spinhash_status spinhash_result_group(const spinhash_result* result, uint32_t rank,
                                      spinhash_ranked_group* out) SPINHASH_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif /* SPINHASH_SPINHASH_H */
