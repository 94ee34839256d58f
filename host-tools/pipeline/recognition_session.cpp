#include "pipeline/recognition_session.hpp"

#include <chrono>
#include <cstring>

namespace spinhash::pipeline {

bool RecognitionSession::init(const Database* db, const RecognizerConfig& cfg, std::string* error) {
  size_t bytes = required_workspace_bytes(cfg);
  if (bytes == 0) {
    *error = "invalid recognizer configuration";
    return false;
  }
  workspace_ = host::AlignedBytes(bytes);
  Status s = recognizer_.init(db, cfg, workspace_.data(), workspace_.size());
  if (s != Status::kOk) {
    *error = std::string("recognizer: ") + status_name(s);
    return false;
  }
  return true;
}

Result RecognitionSession::recognize(const std::vector<double>& xyz) {
  auto start = std::chrono::steady_clock::now();
  const uint64_t n = xyz.size() / 3u;
  // More points than a uint32 counts is more than any workspace holds: refuse.
  Result r = n > 0xFFFFFFFFull ? Result{} : recognizer_.recognize(xyz.data(), static_cast<uint32_t>(n));
  if (n > 0xFFFFFFFFull) r.status = Status::kTooManyPoints;
  last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::string model_name(const Database& db, uint32_t model) {
  const char* name = db.model(model).name;
  return std::string(name, strnlen(name, kMaxModelNameBytes));
}

}  // namespace spinhash::pipeline
