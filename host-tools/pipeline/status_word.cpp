#include "pipeline/status_word.hpp"

namespace spinhash::pipeline {

const char* status_word(Status s) {
  switch (s) {
    case Status::kOk: return "ok";
    case Status::kEmptyCloud: return "empty_cloud";
    case Status::kTooManyPoints: return "too_many_points";
    case Status::kNotEnoughFeatures: return "not_enough_features";
    case Status::kInvalidArgument: return "invalid_argument";
    case Status::kWorkspaceTooSmall: return "workspace_too_small";
    case Status::kTileTooLarge: return "tile_too_large";
    case Status::kTooManyObjects: return "too_many_objects";
    case Status::kWindowOverflow: return "window_overflow";
    case Status::kStreamFlushed: return "stream_flushed";
    default: return "error";
  }
}

}  // namespace spinhash::pipeline
