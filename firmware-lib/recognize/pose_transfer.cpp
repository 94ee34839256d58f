// Look-alike pose transfer (not in the paper; BRAN). In a database with many
// look-alikes, the W candidates of a query feature are shared among them, so
// the true model may get no correct doublet while a look-alike's pose fits
// it within Delta. The best poses found are therefore also verified, through
// the same likelihood, on the models whose bounding boxes (each in its own
// frame) are nearest the posed model's; the least-squares refinement of the
// leading models then settles the fit. A model in another frame convention
// just scores badly at a lent pose and changes nothing; it is dropped after
// a few dozen features when clearly worse than the pose's source (the
// preemptive checks of verify_pose), which most of them are. Bounded:
// kTransferPoses x kMaxTransferModels extra verifications, after the
// hypothesis budget (counted in RecognitionStats::transferred).
#include "recognize/box_distance.hpp"
#include "recognize/search_context.hpp"
#include "spinhash/limits.hpp"
#include "util/top_n.hpp"

namespace spinhash {
namespace {

constexpr uint32_t kTransferPoses = 4;  // leading models whose poses are lent

}  // namespace

void transfer_poses(SearchContext& ctx) {
  const uint32_t model_count = ctx.db.model_count();
  const uint32_t wanted = ctx.cfg.transfer_models;  // <= kMaxTransferModels (config_valid)
  if (wanted == 0u) return;
  uint32_t sources[kTransferPoses];
  const uint32_t n_sources = top_n(
      model_count, kTransferPoses, sources, [&](uint32_t m) { return has_hypothesis(ctx, m); },
      [&](uint32_t a, uint32_t b) { return scores_higher(ctx, a, b); });
  RigidPose poses[kTransferPoses];  // copied: consider_pose may replace a source's own pose
  float scores[kTransferPoses];
  for (uint32_t i = 0; i < n_sources; ++i) {
    poses[i] = ctx.buf.best[sources[i]].pose;
    scores[i] = ctx.buf.best[sources[i]].score;
  }
  uint32_t targets[kMaxTransferModels];
  for (uint32_t i = 0; i < n_sources; ++i) {
    const uint32_t n =
        nearest_by_box(ctx.db, sources[i], wanted, targets, [&](uint32_t m) { return m != sources[i]; });
    for (uint32_t t = 0; t < n; ++t) {
      ++ctx.stats.transferred;
      consider_pose(ctx, targets[t], poses[i], scores[i]);
    }
  }
}

}  // namespace spinhash
