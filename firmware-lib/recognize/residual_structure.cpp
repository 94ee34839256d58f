// Whether the first model's misfit is the scan's noise or a shape (not in
// the paper): the ranking compares models with each other, so a vehicle
// outside the database that differs from its nearest model by a few
// centimetres (a hood 0.1 m longer, a roof lower) is named as that model
// with a wide margin. What gives it away is that its residuals are not
// noise: they share an offset over a patch of the surface. A one-way
// analysis of variance: the query features' signed distances to the
// model's surface, grouped by the surface cell they land on
// (RankParams::residual_cell of the model's frame and the facing of the
// model feature matched), give
//   F = (sum over cells of n_c mean_c^2 / cells) / (scatter within the cells)
// about 1 for a right model whatever the noise and well above it when a
// patch sits off the surface. It withholds `confident` from such
// an answer and orders the first two models of a look-alike group, which
// the likelihood cannot separate. Bounded: one exact nearest-feature search
// and one sample per query feature, and a heap sort of the samples.
#include "recognize/residual_structure.hpp"

#include <cmath>

#include "util/heap_sort.hpp"

namespace spinhash {
namespace {

constexpr uint32_t kCellBitsPerAxis = 9u;  // 512 cells along each axis (256 m of 0.5 m cells)
constexpr uint32_t kMaxCellIndex = (1u << kCellBitsPerAxis) - 1u;
constexpr uint32_t kFacings = 6u;    // +-x, +-y, +-z of the matched model normal
constexpr float kNoEvidence = 0.0f;  // F when too few features share cells to tell

// The matched model feature's cell: its box cell along each axis and the
// axis its normal faces most, so the two sides of a thin panel stay apart.
uint32_t cell_of(const OrientedPoint& m, const blob::ModelRecord& rec, float cell_size) {
  uint32_t key = 0;
  for (int a = 0; a < 3; ++a) {
    const float i = (m.p[a] - rec.bbox_min[a]) / cell_size;
    const uint32_t c =
        i <= 0.0f ? 0u : (i >= static_cast<float>(kMaxCellIndex) ? kMaxCellIndex : static_cast<uint32_t>(i));
    key = (key << kCellBitsPerAxis) | c;
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(m.n[a]) > std::fabs(m.n[axis])) axis = a;
  return key * kFacings + 2u * static_cast<uint32_t>(axis) + (m.n[axis] > 0.0f ? 1u : 0u);
}

// Cell by cell, in the samples' sorted order: the sums of the F statistic.
// Cells with fewer than min_features say nothing of their mean.
struct CellSums {
  uint32_t min_features = 0;
  float between = 0.0f;  // sum of n_c mean_c^2
  float within = 0.0f;   // sum of squared deviations from each cell's mean
  uint32_t cells = 0;
  uint32_t samples = 0;
  void add_cell(const ResidualSample* s, uint32_t n) {
    if (n < min_features) return;
    float sum = 0.0f, sum2 = 0.0f;
    for (uint32_t i = 0; i < n; ++i) sum += s[i].residual, sum2 += s[i].residual * s[i].residual;
    const float mean = sum / static_cast<float>(n);
    between += sum * mean;
    const float dev = sum2 - sum * mean;
    within += dev > 0.0f ? dev : 0.0f;
    ++cells;
    samples += n;
  }
};

}  // namespace

float residual_structure(const SearchContext& ctx, uint32_t model, const RigidPose& pose) {
  const LikelihoodParams lp = make_surface_params(ctx.params, ctx.db);
  const RankParams& p = ctx.params.rank;
  const blob::ModelRecord& rec = ctx.db.model(model);
  const Eigen::Matrix3f rt = pose.rotation.transpose();
  ResidualSample* samples = ctx.buf.residuals;
  uint32_t n = 0;
  for (uint32_t l = 0; l < ctx.query.count; ++l) {
    Eigen::Vector3f x, nq;
    query_in_model_frame(ctx.query, l, rt, pose.translation, &x, &nq);
    const NearestFeature near = find_nearest_model_feature(ctx.db, rec, x, nq, lp);
    if (near.feature < 0) continue;
    const OrientedPoint m = ctx.model_point(static_cast<uint32_t>(near.feature));
    samples[n++] = ResidualSample{cell_of(m, rec, p.residual_cell), l, offset_along_normal(m, x)};
  }
  // By cell, then by feature: the order of every sum is fully determined.
  heap_sort(samples, n, [](const ResidualSample& a, const ResidualSample& b) {
    return a.cell < b.cell || (a.cell == b.cell && a.feature < b.feature);
  });
  CellSums sums;
  sums.min_features = p.residual_min_cell_features;
  for (uint32_t start = 0, i = 1; i <= n; ++i)
    if (i == n || samples[i].cell != samples[start].cell) {
      sums.add_cell(samples + start, i - start);
      start = i;
    }
  if (sums.cells == 0u || sums.samples <= sums.cells || !(sums.within > 0.0f)) return kNoEvidence;
  const float between_mean = sums.between / static_cast<float>(sums.cells);
  const float within_mean = sums.within / static_cast<float>(sums.samples - sums.cells);
  return between_mean / within_mean;
}

void order_twins_by_residuals(const SearchContext& ctx, RankedModel* ranking, uint32_t group_size) {
  if (group_size < 2u || !ranking[0].has_pose || !ranking[1].has_pose) return;
  const float first = residual_structure(ctx, ranking[0].model, ctx.buf.best[ranking[0].model].pose);
  const float second = residual_structure(ctx, ranking[1].model, ctx.buf.best[ranking[1].model].pose);
  // Without evidence on either side the likelihood's order stands.
  if (first == kNoEvidence || second == kNoEvidence || !(second < first)) return;
  const RankedModel lead = ranking[0];
  ranking[0] = ranking[1];
  ranking[1] = lead;
}

}  // namespace spinhash
