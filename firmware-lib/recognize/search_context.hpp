// State shared by the three recognition modes during one recognize() call.
#pragma once
#include <cstdint>

#include "index/candidates.hpp"
#include "match/doublet.hpp"
#include "match/likelihood.hpp"
#include "spinhash/features.hpp"
#include "spinhash/recognizer.hpp"
#include "util/rng.hpp"

namespace spinhash {

// Best hypothesis of one model so far (gamma_i of section 9).
struct ModelBest {
  RigidPose pose;
  float score;
  uint32_t hypotheses;
  uint32_t inliers;
  bool has_score;
  bool final_score;  // rescored on every query feature
};

struct RecognizerBuffers {
  FeatureExtractor extractor;
  LshSearcher searcher;
  uint8_t* query_spins = nullptr;     // max_features * max_spin_dims
  Candidate* candidates = nullptr;    // max_features * candidate_stride
  uint32_t* candidate_count = nullptr;// max_features
  float* cumulative = nullptr;        // max_features: sampling weights, running sum
  ModelBest* best = nullptr;          // max_models
  RankedModel* ranking = nullptr;     // max_models
  uint32_t candidate_stride = 0;      // largest W of any mode
};

struct SearchContext {
  const Database& db;
  const RecognizerConfig& cfg;
  RecognizerBuffers& buf;
  QueryFeatures query;
  LikelihoodParams likelihood;
  DoubletTolerance tolerance;
  float d_min;
  float theta_min;
  RecognitionStats& stats;
  Pcg32 rng;
  const float* cumulative = nullptr;  // doublet draw weights (running sums); null = uniform

  Candidate* candidates_of(uint32_t feature) const {
    return buf.candidates + static_cast<size_t>(feature) * buf.candidate_stride;
  }
  OrientedPoint query_point(uint32_t feature) const;
  OrientedPoint model_point(uint32_t feature) const;
};

// Draws two distinct query features by the cumulative weights (uniform when
// null) until they satisfy the stability constraints of eq. 3, at most
// kMaxStabilityRetries times. false when no stable pair was drawn.
bool draw_stable_doublet(SearchContext& ctx, uint32_t* k, uint32_t* l, DoubletShape* shape);

// Hypothesis budget: BRAN caps the total, SRAN each model's own RANSAC.
struct HypothesisCaps {
  uint32_t total;
  uint32_t per_model;
};

// Cascade, pose, verification and gamma_i update for query features (k, l)
// matched to model features (fu, fv) of `model`. false once the budget is spent.
bool evaluate_pair(SearchContext& ctx, uint32_t model, uint32_t k, uint32_t l,
                   const DoubletShape& shape, uint32_t fu, uint32_t fv, const HypothesisCaps& caps);

void run_bran(SearchContext& ctx);
// Rescores the leading models on all query features (refining their poses
// when asked) and puts every score on the all-features scale (BRAN, SRAN).
void finalise_scores(SearchContext& ctx, bool refine);
void run_sran(SearchContext& ctx);
void run_sind(SearchContext& ctx);

}  // namespace spinhash
