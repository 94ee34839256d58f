// The C99 API (include/spinhash/spinhash.h) over the C++ core: the C++
// objects are placed in the caller's opaque storage; nothing is allocated.
#include "spinhash/spinhash.h"

#include <new>

#include "c_api/config_bridge.hpp"
#include "c_api/log.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash {
namespace {

// What a spinhash_recognizer holds: the recognizer and the C database it reads
// (so results can name their models).
struct RecognizerSlot {
  Recognizer recognizer;
  const spinhash_database* database;
};

static_assert(sizeof(Database) <= SPINHASH_DATABASE_STORAGE_BYTES, "raise SPINHASH_DATABASE_STORAGE_BYTES");
static_assert(sizeof(RecognizerSlot) <= SPINHASH_RECOGNIZER_STORAGE_BYTES,
              "raise SPINHASH_RECOGNIZER_STORAGE_BYTES");
static_assert(alignof(Database) <= alignof(spinhash_database), "database storage under-aligned");
static_assert(alignof(RecognizerSlot) <= alignof(spinhash_recognizer), "recognizer storage under-aligned");
static_assert(alignof(spinhash_database) == SPINHASH_STORAGE_ALIGNMENT, "storage alignment macro is stale");
static_assert(SPINHASH_BUFFER_ALIGNMENT == kBufferAlignment, "buffer alignment macro is stale");

// The C enum and Status are the same list (status_list.h); the C enum's
// values are ints, as Status's.
#define SPINHASH_SAME_STATUS(cxx, value, c, word, message)                               \
  static_assert(static_cast<int32_t>(SPINHASH_##c) == static_cast<int32_t>(Status::cxx), \
                "spinhash_status and spinhash::Status disagree on " #c);
SPINHASH_STATUS_LIST(SPINHASH_SAME_STATUS)
#undef SPINHASH_SAME_STATUS

spinhash_status to_c(Status s) { return static_cast<spinhash_status>(static_cast<int32_t>(s)); }

const Database* view(const spinhash_database* db) {
  const Database* d = db == nullptr ? nullptr : reinterpret_cast<const Database*>(db->bytes);
  return d != nullptr && d->is_open() ? d : nullptr;
}

RecognizerSlot* slot(spinhash_recognizer* rec) {
  return rec == nullptr ? nullptr : reinterpret_cast<RecognizerSlot*>(rec->bytes);
}

spinhash_status finish(const RecognizerSlot& sl, const Result& r, spinhash_result* out) {
  *out = spinhash_result{};
  out->status = static_cast<int32_t>(r.status);
  out->ranking_count = r.status == Status::kOk ? r.ranking_count : 0u;
  out->confident = r.confident ? 1u : 0u;
  out->group_size = r.status == Status::kOk ? r.group_size : 0u;
  out->class_ranking_count = r.status == Status::kOk ? r.class_ranking_count : 0u;
  out->class_confident = r.status == Status::kOk && r.class_confident ? 1u : 0u;
  out->class_ranking_ = r.class_ranking;
  static_assert(SPINHASH_CALIBRATED_LEVELS == kCalibratedLevels, "the C levels are answer_levels.h's");
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
    out->level_confident[l] = r.status == Status::kOk && r.levels[l].confident ? 1u : 0u;
    out->level_evidence[l] = r.levels[l].evidence;
  }
  out->level = r.status == Status::kOk ? static_cast<uint32_t>(r.level) : 0u;
  out->group_ranking_count = r.status == Status::kOk ? r.group_ranking_count : 0u;
  out->group_ranking_ = r.group_ranking;
  to_c_stats(r.stats, &out->stats);
  out->ranking_ = r.ranking;
  out->database_ = sl.database;
  if (r.status != Status::kOk)
    log_message(LogLevel::kWarning, SPINHASH_LOG_TEXT("recognize: "), status_name(r.status));
  return to_c(r.status);
}

template <typename T>
spinhash_status recognize(spinhash_recognizer* rec, const T* xyz, uint32_t count, spinhash_result* out) {
  if (out == nullptr) return SPINHASH_INVALID_ARGUMENT;
  *out = spinhash_result{};
  RecognizerSlot* sl = slot(rec);
  if (sl == nullptr || sl->database == nullptr) {
    out->status = SPINHASH_NOT_OPEN;
    return SPINHASH_NOT_OPEN;
  }
  return finish(*sl, sl->recognizer.recognize(xyz, count), out);
}

}  // namespace
}  // namespace spinhash

using namespace spinhash;

extern "C" {

const char* spinhash_status_name(int32_t status) SPINHASH_NOEXCEPT {
  return status_name(static_cast<Status>(status));
}

void spinhash_default_config(spinhash_config* config) SPINHASH_NOEXCEPT {
  if (config != nullptr) to_c_config(RecognizerConfig{}, config);
}

size_t spinhash_workspace_bytes(const spinhash_config* config) SPINHASH_NOEXCEPT {
  RecognizerConfig cfg;
  if (config == nullptr || !from_c_config(*config, &cfg)) return 0;
  return required_workspace_bytes(cfg);
}

spinhash_status spinhash_database_open(spinhash_database* db, const void* bytes,
                                       size_t size) SPINHASH_NOEXCEPT {
  if (db == nullptr) return SPINHASH_INVALID_ARGUMENT;
  Database* d = new (db->bytes) Database();  // closed until open succeeds
  Status s = Database::open(bytes, size, d);
  if (s != Status::kOk) log_message(LogLevel::kError, SPINHASH_LOG_TEXT("database open: "), status_name(s));
  return to_c(s);
}

uint32_t spinhash_database_model_count(const spinhash_database* db) SPINHASH_NOEXCEPT {
  const Database* d = view(db);
  return d == nullptr ? 0u : d->model_count();
}

const char* spinhash_database_model_name(const spinhash_database* db, uint32_t index) SPINHASH_NOEXCEPT {
  const Database* d = view(db);
  if (d == nullptr || index >= d->model_count()) return nullptr;
  return d->model(index).name;  // NUL-terminated: checked by Database::open
}

uint32_t spinhash_database_model_class(const spinhash_database* db, uint32_t index) SPINHASH_NOEXCEPT {
  const Database* d = view(db);
  if (d == nullptr || index >= d->model_count()) return SPINHASH_CLASS_COUNT;
  return d->model(index).vehicle_class;  // < SPINHASH_CLASS_COUNT: checked by Database::open
}

uint32_t spinhash_database_model_group(const spinhash_database* db, uint32_t index) SPINHASH_NOEXCEPT {
  const Database* d = view(db);
  if (d == nullptr || index >= d->model_count()) return SPINHASH_GROUP_COUNT;
  return static_cast<uint32_t>(model_group(d->model(index)));
}

const char* spinhash_class_name(uint32_t vehicle_class) SPINHASH_NOEXCEPT {
  return vehicle_class_name(vehicle_class);
}

uint32_t spinhash_class_group(uint32_t vehicle_class) SPINHASH_NOEXCEPT {
  return static_cast<uint32_t>(vehicle_group_of(vehicle_class));
}

const char* spinhash_group_name(uint32_t group) SPINHASH_NOEXCEPT { return vehicle_group_name(group); }

const char* spinhash_level_name(uint32_t level) SPINHASH_NOEXCEPT { return answer_level_name(level); }

spinhash_status spinhash_recognizer_init(spinhash_recognizer* rec, const spinhash_database* db,
                                         const spinhash_config* config, void* workspace,
                                         size_t workspace_bytes) SPINHASH_NOEXCEPT {
  if (rec == nullptr) return SPINHASH_INVALID_ARGUMENT;
  RecognizerSlot* sl = new (rec->bytes) RecognizerSlot{Recognizer(), nullptr};
  RecognizerConfig cfg;
  if (config == nullptr || !from_c_config(*config, &cfg)) return SPINHASH_INVALID_ARGUMENT;
  Status s = sl->recognizer.init(view(db), cfg, workspace, workspace_bytes);
  if (s != Status::kOk) {
    log_message(LogLevel::kError, SPINHASH_LOG_TEXT("recognizer init: "), status_name(s));
    return to_c(s);
  }
  sl->database = db;
  return SPINHASH_OK;
}

spinhash_status spinhash_recognize_f32(spinhash_recognizer* rec, const float* xyz, uint32_t count,
                                       spinhash_result* result) SPINHASH_NOEXCEPT {
  return recognize(rec, xyz, count, result);
}

spinhash_status spinhash_recognize_f64(spinhash_recognizer* rec, const double* xyz, uint32_t count,
                                       spinhash_result* result) SPINHASH_NOEXCEPT {
  return recognize(rec, xyz, count, result);
}

spinhash_status spinhash_result_entry(const spinhash_result* result, uint32_t rank,
                                      spinhash_ranked_model* out) SPINHASH_NOEXCEPT {
  if (result == nullptr || out == nullptr || result->status != SPINHASH_OK || rank >= result->ranking_count ||
      result->ranking_ == nullptr)
    return SPINHASH_INVALID_ARGUMENT;
  const RankedModel& m = static_cast<const RankedModel*>(result->ranking_)[rank];
  *out = spinhash_ranked_model{};
  out->model = m.model;
  out->score = m.score;
  out->has_pose = m.has_pose ? 1u : 0u;
  out->hypotheses = m.hypotheses;
  out->inliers = m.inliers;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out->pose[4 * r + c] = static_cast<double>(m.pose.rotation[3 * r + c]);
    out->pose[4 * r + 3] = m.pose.translation[r];
  }
  out->pose[15] = 1.0;
  out->name = spinhash_database_model_name(result->database_, m.model);
  return SPINHASH_OK;
}

spinhash_status spinhash_result_class(const spinhash_result* result, uint32_t rank,
                                      spinhash_ranked_class* out) SPINHASH_NOEXCEPT {
  if (result == nullptr || out == nullptr || result->status != SPINHASH_OK ||
      rank >= result->class_ranking_count || result->class_ranking_ == nullptr)
    return SPINHASH_INVALID_ARGUMENT;
  const RankedClass& c = static_cast<const RankedClass*>(result->class_ranking_)[rank];
  *out = spinhash_ranked_class{};
  out->vehicle_class = c.vehicle_class;
  out->score = c.score;
  out->model = c.model;
  out->name = vehicle_class_name(c.vehicle_class);
  return SPINHASH_OK;
}

spinhash_status spinhash_result_group(const spinhash_result* result, uint32_t rank,
                                      spinhash_ranked_group* out) SPINHASH_NOEXCEPT {
  if (result == nullptr || out == nullptr || result->status != SPINHASH_OK ||
      rank >= result->group_ranking_count || result->group_ranking_ == nullptr)
    return SPINHASH_INVALID_ARGUMENT;
  const RankedGroup& g = static_cast<const RankedGroup*>(result->group_ranking_)[rank];
  *out = spinhash_ranked_group{};
  out->group = g.group;
  out->score = g.score;
  out->model = g.model;
  out->name = vehicle_group_name(g.group);
  return SPINHASH_OK;
}

}  // extern "C"
