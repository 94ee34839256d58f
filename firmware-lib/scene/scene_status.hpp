// The outcome of a run of the scene's windows: the worse of two, a lost
// window before points that came too late, before a full list of objects.
#pragma once
#include "spinhash/status.hpp"

namespace spinhash {

inline Status worse_scene_status(Status a, Status b) {
  if (a == Status::kWindowOverflow || b == Status::kWindowOverflow) return Status::kWindowOverflow;
  if (a == Status::kPointsLate || b == Status::kPointsLate) return Status::kPointsLate;
  return a != Status::kOk ? a : b;
}

}  // namespace spinhash
