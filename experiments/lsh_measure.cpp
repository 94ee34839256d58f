#include "lsh_measure.hpp"

#include <algorithm>
#include <chrono>

#include "blob/blob_writer.hpp"
#include "db/lsh_tables.hpp"
#include "db/model_features.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/lsh.hpp"
// The core's own candidate search, quantisation and L1 distance: the recall
// measured is that of the code that runs onboard, not of a re-implementation.
#include "spinhash/internal/l1_distance.hpp"
#include "spinhash/internal/lsh_search.hpp"
#include "spinhash/internal/spin_quantize.hpp"

namespace spinhash::experiment {
namespace {

Eigen::Vector3d model_position(const Database& db, uint32_t f) {
  const float* p = db.positions() + 3u * static_cast<size_t>(f);
  return {p[0], p[1], p[2]};
}

// True-model features within `delta` of p under the true pose.
std::vector<uint32_t> correct_features(const Database& db, uint32_t model, const Eigen::Matrix4d& pose,
                                       const Eigen::Vector3d& p, double delta) {
  std::vector<uint32_t> out;
  const blob::ModelRecord& rec = db.model(model);
  for (uint32_t f = rec.first_feature; f < rec.first_feature + rec.feature_count; ++f) {
    Eigen::Vector3d x = pose.topLeftCorner<3, 3>() * model_position(db, f) + pose.topRightCorner<3, 1>();
    if ((x - p).norm() <= delta) out.push_back(f);
  }
  return out;
}

void exhaustive_answer(const Database& db, uint32_t w, ProbeFeature* pf) {
  const uint32_t n = db.feature_count(), dims = db.spin_dims();
  std::vector<uint32_t> dist(n);
  for (uint32_t f = 0; f < n; ++f) dist[f] = l1_distance(pf->spin.data(), db.spin(f), dims);
  std::vector<uint32_t> sorted = dist;
  const uint32_t wi = std::min(w, n) - 1u;
  std::nth_element(sorted.begin(), sorted.begin() + wi, sorted.end());
  pf->w_distance = sorted[wi];
  pf->nn_distance = *std::min_element(dist.begin(), dist.end());
  for (uint32_t f : pf->correct) pf->exhaustive_match = pf->exhaustive_match || dist[f] <= pf->w_distance;
  uint32_t within = 0, true_model = 0;
  for (uint32_t f = 0; f < n; ++f)
    if (dist[f] <= pf->w_distance) {
      ++within;
      true_model += db.feature_models()[f] == pf->model ? 1u : 0u;
    }
  pf->exhaustive_true_share = within ? static_cast<double>(true_model) / within : 0.0;
}

// Tables for (K, L) swapped into a copy of the content, opened as a Database.
struct ConfigDatabase {
  host::AlignedBytes bytes;
  Database db;
};

bool open_with_tables(const MemoryDatabase& mdb, const host::LshTables& t, uint32_t k, uint32_t l,
                      ConfigDatabase* out, std::string* error) {
  host::BlobContent c = mdb.content;
  c.lsh_bits = t.bits;
  c.lsh_offsets = t.offsets;
  c.lsh_entries = t.entries;
  c.params.lsh_bits = k;
  c.params.lsh_tables = l;
  c.params.lsh_buckets = t.buckets;
  c.params.lsh_dc = t.d_c;
  return host::open_content(c, &out->bytes, &out->db, error);
}

void measure_recall(const Database& db, const RecognizerConfig& cfg, const std::vector<ProbeFeature>& probes,
                    LshConfigResult* r) {
  Arena counter;
  LshSearcher sizing;
  sizing.carve(counter, cfg.candidates.max_bucket_scan);
  host::AlignedBytes buffer(counter.used());
  Arena arena(buffer.data(), buffer.size());
  LshSearcher searcher;
  searcher.carve(arena, cfg.candidates.max_bucket_scan);
  const uint32_t w = std::min(cfg.candidates.top_w, kMaxCandidates);
  std::vector<Candidate> cand(w);
  uint64_t nn = 0, match = 0, ncand = 0, scanned = 0, truncated = 0;
  double topw = 0.0, share = 0.0, seconds = 0.0;
  for (const ProbeFeature& p : probes) {
    SearchStats st;
    auto start = std::chrono::steady_clock::now();
    uint32_t n = searcher.search(db, p.spin.data(), w, cand.data(), &st);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bool has_nn = false, has_match = false;
    uint32_t within_w = 0, true_model = 0;
    for (uint32_t i = 0; i < n; ++i) {
      has_nn = has_nn || cand[i].distance == p.nn_distance;
      within_w += cand[i].distance <= p.w_distance ? 1u : 0u;
      true_model += db.feature_models()[cand[i].feature] == p.model ? 1u : 0u;
      has_match = has_match || std::binary_search(p.correct.begin(), p.correct.end(), cand[i].feature);
    }
    nn += has_nn;
    match += has_match;
    topw += static_cast<double>(std::min(within_w, w)) / w;
    share += n ? static_cast<double>(true_model) / n : 0.0;
    ncand += n;
    scanned += st.entries_scanned;
    truncated += st.truncated;
    r->features_with_match += p.correct.empty() ? 0u : 1u;
  }
  const double count = std::max<double>(1.0, static_cast<double>(probes.size()));
  r->features = static_cast<uint32_t>(probes.size());
  r->nn_recall = nn / count;
  r->topw_recall = topw / count;
  r->match_recall = r->features_with_match ? static_cast<double>(match) / r->features_with_match : 0.0;
  r->true_model_share = share / count;
  r->mean_candidates = ncand / count;
  r->mean_entries_scanned = scanned / count;
  r->truncated_share = truncated / count;
  r->us_per_lookup = 1e6 * seconds / count;
}

void measure_collisions(const Database& db, const std::vector<ProbeFeature>& probes, uint32_t pair_features,
                        const std::vector<uint32_t>& ranges, double bin_width, uint32_t bins,
                        LshConfigResult* r) {
  const blob::Params& p = db.params();
  const uint32_t n = db.feature_count(), dims = db.spin_dims(), k = p.lsh_bits, l = p.lsh_tables;
  std::vector<uint64_t> keys(static_cast<size_t>(l) * n);  // every feature's key in every table
  for (uint32_t t = 0; t < l; ++t)
    for (uint32_t f = 0; f < n; ++f)
      keys[static_cast<size_t>(t) * n + f] = lsh_key(db.lsh_bits(t), k, db.spin(f));
  std::vector<uint8_t> clamped(static_cast<size_t>(n) * dims);
  for (uint32_t f = 0; f < n; ++f)
    for (uint32_t d = 0; d < dims; ++d)
      clamped[static_cast<size_t>(f) * dims + d] =
          static_cast<uint8_t>(std::min<uint32_t>(db.spin(f)[d], ranges[d]));
  r->pairs.assign(bins, 0);
  r->collisions.assign(bins, 0);
  const size_t stride = std::max<size_t>(1, probes.size() / std::max<uint32_t>(1, pair_features));
  std::vector<uint64_t> qkeys(l);
  std::vector<uint8_t> qc(dims);
  for (size_t i = 0; i < probes.size(); i += stride) {
    const uint8_t* s = probes[i].spin.data();
    for (uint32_t t = 0; t < l; ++t) qkeys[t] = lsh_key(db.lsh_bits(t), k, s);
    for (uint32_t d = 0; d < dims; ++d) qc[d] = static_cast<uint8_t>(std::min<uint32_t>(s[d], ranges[d]));
    for (uint32_t f = 0; f < n; ++f) {
      uint32_t d = l1_distance(qc.data(), clamped.data() + static_cast<size_t>(f) * dims, dims);
      const uint32_t b = static_cast<uint32_t>(d / bin_width);
      if (b >= bins) continue;
      bool hit = false;
      for (uint32_t t = 0; t < l && !hit; ++t) hit = keys[static_cast<size_t>(t) * n + f] == qkeys[t];
      ++r->pairs[b];
      r->collisions[b] += hit ? 1u : 0u;
    }
  }
}

}  // namespace

bool probe_features(const MemoryDatabase& mdb, const RecognizerConfig& cfg, const Query& q,
                    uint32_t per_query, std::vector<ProbeFeature>* out, std::string* error) {
  host::ModelFeatures mf;
  const Database& db = mdb.db;
  if (!host::extract_model_features(q.xyz, db.feature_params(), cfg.max_points, cfg.max_features, &mf, error))
    return false;
  const uint32_t dims = db.spin_dims();
  const uint32_t take = std::min(per_query, mf.count);
  for (uint32_t i = 0; i < take; ++i) {
    const uint32_t f = static_cast<uint32_t>(static_cast<uint64_t>(i) * mf.count / take);  // evenly spread
    ProbeFeature pf;
    pf.spin.resize(dims);
    quantize_spin(mf.spins.data() + static_cast<size_t>(f) * dims, dims, db.params().spin_quant_scale,
                  pf.spin.data());
    pf.position = {mf.positions[3u * f], mf.positions[3u * f + 1u], mf.positions[3u * f + 2u]};
    pf.model = q.model;
    pf.correct = correct_features(db, q.model, q.true_pose, pf.position, cfg.draws.delta);
    exhaustive_answer(db, cfg.candidates.top_w, &pf);
    out->push_back(std::move(pf));
  }
  return true;
}

bool measure_lsh_config(const MemoryDatabase& mdb, const host::BuildOptions& build,
                        const RecognizerConfig& cfg, const std::vector<ProbeFeature>& probes,
                        uint32_t pair_features, const std::vector<uint32_t>& ranges, double bin_width,
                        uint32_t bins, LshConfigResult* out, std::string* error) {
  const uint32_t dims = mdb.db.spin_dims(), n = mdb.db.feature_count();
  host::LshTables t = host::build_lsh_tables(mdb.content.spins, dims, n, out->l, out->k,
                                             build.lsh_range_quantile, build.seed);
  out->buckets = t.buckets;
  out->max_bucket = t.max_bucket;
  out->mean_bucket = t.mean_bucket;
  ConfigDatabase cdb;
  if (!open_with_tables(mdb, t, out->k, out->l, &cdb, error)) return false;
  measure_recall(cdb.db, cfg, probes, out);
  measure_collisions(cdb.db, probes, pair_features, ranges, bin_width, bins, out);
  return true;
}

}  // namespace spinhash::experiment
