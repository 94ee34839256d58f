// A Recognizer with a heap-allocated workspace of exactly the required size:
// the host-side way to drive the core.
#pragma once
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash::pipeline {

class RecognitionSession {
 public:
  // false with a message when the config is invalid or does not fit the database.
  bool init(const Database* db, const RecognizerConfig& cfg, std::string* error);
  Result recognize(const std::vector<double>& xyz);
  // Wall time of the last recognize(), milliseconds.
  double last_ms() const { return last_ms_; }
  const RecognizerConfig& config() const { return recognizer_.config(); }

 private:
  host::AlignedBytes workspace_;
  Recognizer recognizer_;
  double last_ms_ = 0.0;
};

// Model names of a result's ranking, best first, for messages.
std::string model_name(const Database& db, uint32_t model);

}  // namespace spinhash::pipeline
