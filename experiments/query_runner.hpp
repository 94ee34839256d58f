// One recognition of a simulated query and what the experiments record of it.
#pragma once
#include <cmath>
#include <cstdint>

#include "pipeline/recognition_session.hpp"
#include "query_set.hpp"

namespace spinhash::experiment {

struct Outcome {
  Status status = Status::kNotOpen;
  uint32_t rank = 0;        // 1-based position of the true model in the ranking; 0: not ranked
  double ms = 0.0;          // wall time of recognize()
  uint32_t hypotheses = 0;  // poses verified
  uint32_t features = 0;    // query features used
  uint32_t ranked = 0;      // models in the ranking
  uint32_t best_model = 0;  // ranked first (valid when ranked > 0)
  bool confident = false;
  uint32_t group_size = 0;  // leading models the scan does not tell apart (Result::group_size)
  bool budget_exhausted = false;
  uint32_t trials = 0;        // doublet draws
  float score_first = 0.0f;   // log-likelihood of the first model (valid when ranked > 0)
  float score_second = 0.0f;  // of the runner-up (valid when ranked > 1)
  uint32_t inliers = 0;       // of the first model
  // Pose of the first model against the scan's true pose (NaN without a pose):
  // the rotation's angle (degrees) and the translation's distance (m).
  double rotation_error_deg = NAN;
  double translation_error_m = NAN;
  // The class level (Result::class_ranking): the first class's id, 0 when none.
  uint32_t class_first = 0;
  float class_lead = NAN;  // the first class's score above the second's (NaN with fewer than two)
  bool class_confident = false;
  float surface_coverage = 0.0f;  // RecognitionStats::surface_coverage
  float scan_density = 0.0f;      // RecognitionStats::scan_density
};

Outcome recognise(pipeline::RecognitionSession& session, const Query& q);

}  // namespace spinhash::experiment
