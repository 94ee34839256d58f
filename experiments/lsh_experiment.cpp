// spinhash-experiment lsh: measured key-collision probability against the
// L1 distance for a few (K, L) beside eq. 2, and the recall of the W
// candidates the index returns (nearest neighbour, exhaustive top W, and a
// geometrically correct model feature).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "config_text.hpp"
#include "db/lsh_tables.hpp"
#include "experiments.hpp"
#include "lsh_measure.hpp"
#include "mesh/vehicle_generator.hpp"
#include "model_set.hpp"
#include "output_dir.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/progress.hpp"
#include "spinhash/limits.hpp"
#include "stats.hpp"

namespace spinhash::experiment {
namespace {

constexpr uint32_t kDistanceBins = 40;
// Binned range, as a share of d_c: beyond it eq. 2 is below 3e-4 for K >= 16
// and L <= 16 (0.5^K * L), and finer bins near 0 follow the steep part.
constexpr double kBinnedShareOfDc = 0.5;
constexpr uint32_t kMaxQueries = 10000;

struct LshArgs {
  std::string out;
  uint32_t models = 56;
  std::vector<uint32_t> k{16, 24, 32};
  std::vector<uint32_t> l{8, 16};
  uint32_t queries = 20;
  uint32_t features_per_query = 100;  // probes per query scan
  uint32_t pair_features = 200;       // probes paired with every database feature
  double noise = 0.05;
  uint64_t seed = 1;
  uint64_t fleet_seed = 1;
};

bool make_probes(const LshArgs& a, const std::vector<pipeline::ModelMesh>& meshes, const MemoryDatabase& mdb,
                 const RecognizerConfig& cfg, std::vector<ProbeFeature>* probes, std::string* error) {
  const QueryCondition cond{a.noise, 0.0, Ground::kNone};
  const uint32_t m = static_cast<uint32_t>(meshes.size());
  pipeline::Progress progress("probe features (exhaustive search)", a.queries);
  for (uint32_t j = 0; j < a.queries; ++j) {
    Query q;
    if (!simulate_query(meshes[j % m].mesh, j % m, j / m, cond, a.seed, 0.0, &q, error) ||
        !probe_features(mdb, cfg, q, a.features_per_query, probes, error))
      return false;
    progress.tick(j + 1);
  }
  return true;
}

// Medians of the nearest-neighbour and nearest-correct distances, clamped L1,
// over the probes that are paired for the collision measurement.
void distance_medians(const MemoryDatabase& mdb, const std::vector<ProbeFeature>& probes,
                      uint32_t pair_features, const std::vector<uint32_t>& ranges, LshRun* run) {
  const uint32_t dims = mdb.db.spin_dims(), n = mdb.db.feature_count();
  auto clamped_l1 = [&](const uint8_t* a, const uint8_t* b) {
    uint32_t s = 0;
    for (uint32_t d = 0; d < dims; ++d) {
      int32_t x = std::min<uint32_t>(a[d], ranges[d]), y = std::min<uint32_t>(b[d], ranges[d]);
      s += static_cast<uint32_t>(x > y ? x - y : y - x);
    }
    return s;
  };
  std::vector<double> nn, match;
  const size_t stride = std::max<size_t>(1, probes.size() / std::max<uint32_t>(1, pair_features));
  for (size_t i = 0; i < probes.size(); i += stride) {
    const ProbeFeature& p = probes[i];
    uint32_t best = ~0u;
    for (uint32_t f = 0; f < n; ++f) best = std::min(best, clamped_l1(p.spin.data(), mdb.db.spin(f)));
    nn.push_back(best);
    if (p.correct.empty()) continue;
    uint32_t bm = ~0u;
    for (uint32_t f : p.correct) bm = std::min(bm, clamped_l1(p.spin.data(), mdb.db.spin(f)));
    match.push_back(bm);
  }
  run->median_nn_distance = median_of(nn);
  run->median_match_distance = median_of(match);
}

int run_lsh(const LshArgs& a) {
  std::string error;
  LshRun run;
  run.out_dir = a.out;
  run.command = invoked_command_line();
  run.queries = a.queries;
  run.pair_features = a.pair_features;
  run.source =
      "procedural fleet of " + std::to_string(a.models) + " (seed " + std::to_string(a.fleet_seed) + ")";
  const host::BuildOptions build;  // library defaults
  const RecognizerConfig cfg;
  run.top_w = cfg.candidates.top_w;
  run.max_bucket_scan = cfg.candidates.max_bucket_scan;
  run.delta = cfg.draws.delta;
  std::vector<pipeline::ModelMesh> meshes = generated_models(a.models, a.fleet_seed);
  std::vector<host::ModelCloud> clouds;
  std::unique_ptr<MemoryDatabase> mdb;
  std::vector<ProbeFeature> probes;
  if (!make_output_dir(a.out, &error) || !model_clouds(meshes, &clouds, &error) ||
      !(mdb = build_memory_database(clouds, build, true, &error)) ||
      !make_probes(a, meshes, *mdb, cfg, &probes, &error)) {
    std::fprintf(stderr, "spinhash-experiment lsh: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  clouds.clear();
  run.database = database_text(*mdb);
  run.database_features = mdb->db.feature_count();
  const std::vector<uint32_t> ranges = host::dimension_ranges(
      mdb->content.spins, mdb->db.spin_dims(), mdb->db.feature_count(), build.lsh_range_quantile);
  for (uint32_t r : ranges) run.d_c += r;
  run.d_c_matches_builder = std::abs(run.d_c - mdb->db.params().lsh_dc) < 0.5;
  run.bins = kDistanceBins;
  run.bin_width = kBinnedShareOfDc * run.d_c / kDistanceBins;
  double match = 0, share = 0, with_match = 0;
  for (const ProbeFeature& p : probes) {
    with_match += p.correct.empty() ? 0 : 1;
    match += p.exhaustive_match ? 1 : 0;
    share += p.exhaustive_true_share;
  }
  run.exhaustive_match_recall = with_match > 0 ? match / with_match : 0.0;
  run.exhaustive_true_model_share = probes.empty() ? 0.0 : share / probes.size();
  distance_medians(*mdb, probes, a.pair_features, ranges, &run);
  for (uint32_t l : a.l)
    for (uint32_t k : a.k) {
      LshConfigResult r;
      r.k = k;
      r.l = l;
      r.is_default = k == build.lsh_bits && l == build.lsh_tables;
      std::fprintf(stderr, "spinhash-experiment lsh: K = %u, L = %u\n", k, l);
      if (!measure_lsh_config(*mdb, build, cfg, probes, a.pair_features, ranges, run.bin_width, kDistanceBins,
                              &r, &error)) {
        std::fprintf(stderr, "spinhash-experiment lsh: %s\n", error.c_str());
        return pipeline::kExitError;
      }
      run.configs.push_back(std::move(r));
    }
  if (!write_lsh_report(run, &error)) {
    std::fprintf(stderr, "spinhash-experiment lsh: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::fprintf(stderr, "spinhash-experiment lsh: wrote %s/summary.md\n", a.out.c_str());
  return pipeline::kExitOk;
}

}  // namespace

void add_lsh_experiment(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<LshArgs>();
  CLI::App* cmd =
      parent->add_subcommand("lsh", "eq. 2 against measured collisions; recall of the W candidates");
  a->out = default_output_dir("lsh");
  cmd->add_option("--out", a->out,
                  "output folder (CSV, plots, summary.md); default out/lsh (git ignores out/)");
  cmd->add_option("--models", a->models, "procedural vehicles in the database")
      ->check(CLI::Range(2u, host::kMaxFleetSize))
      ->capture_default_str();
  cmd->add_option("--k", a->k, "bits per key (K) to try")
      ->delimiter(',')
      ->check(CLI::Range(1u, kMaxLshBits))
      ->capture_default_str();
  cmd->add_option("--l", a->l, "tables (L) to try")
      ->delimiter(',')
      ->check(CLI::Range(1u, kMaxLshTables))
      ->capture_default_str();
  cmd->add_option("--queries", a->queries, "query scans (models in turn)")
      ->check(CLI::Range(1u, kMaxQueries))
      ->capture_default_str();
  cmd->add_option("--features-per-query", a->features_per_query, "query features probed per scan")
      ->check(CLI::Range(1u, kMaxQueryFeaturesLimit))
      ->capture_default_str();
  cmd->add_option("--pair-features", a->pair_features,
                  "probes paired with every database feature (collisions)")
      ->check(CLI::Range(1u, 1000000u))
      ->capture_default_str();
  cmd->add_option("--noise", a->noise, "query noise, m along the ray")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "seed of the query scans")->capture_default_str();
  cmd->add_option("--fleet-seed", a->fleet_seed, "seed of the procedural fleet")->capture_default_str();
  cmd->callback([a, exit_code]() { *exit_code = run_lsh(*a); });
}

}  // namespace spinhash::experiment
