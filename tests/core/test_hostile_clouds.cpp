// recognize() on hostile input: degenerate, non-finite, georeferenced, over-size
// and unknown clouds, bad workspaces, null pointers and invalid configs. Each
// must give its documented status (docs/robustness.md), never a crash or a
// confident answer it cannot back. No files: these also run under QEMU.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr uint32_t kQueryModel = 3;  // the tank-like toy: distinct from the others
constexpr double kQueryYaw = 0.7;
constexpr double kNoise = 0.02;  // m
constexpr uint64_t kNoiseSeed = 11;
constexpr float kToySpacing = 0.05f;  // m, as the toy database's model clouds

// Smaller feature and hypothesis budgets than the defaults keep each query
// well under a second under QEMU; the toy views are still recognised.
RecognizerConfig fast_config() {
  constexpr uint32_t kFeatures = 256;
  constexpr uint32_t kHypotheses = 1500;
  RecognizerConfig cfg;
  cfg.max_features = kFeatures;
  cfg.draws.max_hypotheses = kHypotheses;
  return cfg;
}

// A recognizer with its own 64-byte aligned workspace.
struct Session {
  host::AlignedBytes workspace;
  Recognizer recognizer;
  explicit Session(const RecognizerConfig& cfg = fast_config()) {
    workspace = host::AlignedBytes(required_workspace_bytes(cfg));
    REQUIRE(recognizer.init(&test::shared_toy_database().db, cfg, workspace.data(), workspace.size()) ==
            Status::kOk);
  }
  Result run(const std::vector<double>& xyz) {
    return recognizer.recognize(xyz.data(), static_cast<uint32_t>(xyz.size() / 3));
  }
  Result run(const std::vector<float>& xyz) {
    return recognizer.recognize(xyz.data(), static_cast<uint32_t>(xyz.size() / 3));
  }
};

std::vector<double> known_query(const double offset[3]) {
  return test::toy_airborne_query(test::toy_vehicle_points(kQueryModel, kToySpacing), kQueryYaw, offset,
                                  kNoise, kNoiseSeed);
}

std::vector<double> known_query() {
  const double origin[3] = {0.0, 0.0, 0.0};
  return known_query(origin);
}

// Degenerate or unknown input: no result, or a result that claims nothing.
void check_not_confident(const Result& r) {
  CAPTURE(static_cast<int>(r.status));
  CHECK((r.status == Status::kOk || r.status == Status::kNotEnoughFeatures));
  CHECK_FALSE(r.confident);
}

}  // namespace

TEST_CASE("a known view is recognised confidently (the control for the cases below)") {
  Session s;
  const Result r = s.run(known_query());
  REQUIRE(r.status == Status::kOk);
  REQUIRE(r.ranking_count > 0);
  CHECK(r.ranking[0].model == kQueryModel);
  CHECK(r.confident);
  CHECK(r.stats.extract.points_nonfinite == 0);
  CHECK(r.stats.extract.points_thinned == 0);
}

TEST_CASE("an empty cloud is kEmptyCloud, with or without a pointer") {
  Session s;
  const float one[3] = {1.0f, 2.0f, 3.0f};
  CHECK(s.recognizer.recognize(static_cast<const float*>(nullptr), 0).status == Status::kEmptyCloud);
  CHECK(s.recognizer.recognize(static_cast<const double*>(nullptr), 0).status == Status::kEmptyCloud);
  const Result r = s.recognizer.recognize(one, 0);
  CHECK(r.status == Status::kEmptyCloud);
  CHECK(r.ranking_count == 0);
  CHECK_FALSE(r.confident);
}

TEST_CASE("one point, or many copies of one point, is kNotEnoughFeatures") {
  Session s;
  const Result one = s.run(std::vector<float>{1.0f, 2.0f, 3.0f});
  CHECK(one.status == Status::kNotEnoughFeatures);
  CHECK_FALSE(one.confident);
  constexpr uint32_t kCopies = 5000;
  std::vector<double> same;
  for (uint32_t i = 0; i < kCopies; ++i)
    for (double v : {431000.5, 4020000.25, 87.0}) same.push_back(v);
  const Result r = s.run(same);
  CHECK(r.status == Status::kNotEnoughFeatures);
  CHECK_FALSE(r.confident);
  CHECK(r.stats.extract.points_in == kCopies);
}

TEST_CASE("collinear clouds give no confident answer") {
  Session s;
  constexpr uint32_t kPoints = 400;
  constexpr double kStep = 0.02;  // m: an 8 m wire
  std::vector<double> line;
  for (uint32_t i = 0; i < kPoints; ++i)
    for (double v : {i * kStep, 0.5 * i * kStep, 2.0}) line.push_back(v);
  check_not_confident(s.run(line));
}

TEST_CASE("planar clouds (ground, a wall) give no confident answer") {
  Session s;
  constexpr float kHalf = 6.0f;  // m: a 12 m square, larger than every toy
  constexpr float kSpacing = 0.1f;
  const std::vector<float> ground = test::plane_grid(kHalf, kSpacing);
  check_not_confident(s.run(ground));
  std::vector<float> wall;  // the same plane stood upright
  for (size_t i = 0; i < ground.size(); i += 3)
    for (float v : {ground[i], 0.0f, ground[i + 1]}) wall.push_back(v);
  check_not_confident(s.run(wall));
}

TEST_CASE("NaN and infinite points are dropped, counted, and change nothing else") {
  Session s;
  const std::vector<double> clean = known_query();
  const Result base = s.run(clean);
  REQUIRE(base.status == Status::kOk);
  const uint32_t best = base.ranking[0].model;
  const float best_score = base.ranking[0].score;

  // Appended bad points: the kept finite points are exactly the clean ones.
  std::vector<double> dirty = clean;
  const double bad[][3] = {
      {kNaN, 0, 0}, {0, kInf, 0}, {0, 0, -kInf}, {kNaN, kNaN, kNaN}, {kInf, -kInf, kNaN}};
  for (const auto& p : bad) dirty.insert(dirty.end(), p, p + 3);
  const Result r = s.run(dirty);
  REQUIRE(r.status == Status::kOk);
  CHECK(r.stats.extract.points_nonfinite == 5);
  CHECK(r.stats.extract.points_in == clean.size() / 3 + 5);
  CHECK(r.ranking[0].model == best);
  CHECK(r.ranking[0].score == best_score);
  CHECK(r.confident == base.confident);

  // Float input too, with the bad points spread through the cloud.
  std::vector<float> f(clean.begin(), clean.end());
  constexpr size_t kEvery = 50;
  uint32_t spoiled = 0;
  for (size_t i = 0; i + 3 <= f.size(); i += 3 * kEvery, ++spoiled)
    f[i + spoiled % 3] = spoiled % 2 ? kNaN : -kInf;
  const Result rf = s.run(f);
  REQUIRE(rf.status == Status::kOk);
  CHECK(rf.stats.extract.points_nonfinite == spoiled);
  CHECK(rf.ranking[0].model == best);
}

TEST_CASE("a cloud of nothing but NaN and infinities is kEmptyCloud, all counted") {
  Session s;
  const std::vector<float> bad = {kNaN, 0, 0, kInf, kInf, kInf, 0, 0, -kInf};
  const Result r = s.run(bad);
  CHECK(r.status == Status::kEmptyCloud);
  CHECK(r.stats.extract.points_nonfinite == 3);
}

TEST_CASE("huge but finite coordinates do not break the pipeline") {
  Session s;
  constexpr float kHuge = 3.0e38f;  // near FLT_MAX: sums and differences overflow float
  std::vector<float> f = {kHuge, kHuge, kHuge, -kHuge, -kHuge, -kHuge, kHuge, -kHuge, 0.0f, 0.0f, 0.0f, 1.0f};
  const Result rf = s.run(f);
  CHECK_FALSE(rf.confident);
  // Double input beyond the float range, plus a real view far away from it.
  std::vector<double> d = known_query();
  for (double v : {1e300, -1e300, 1e300, 1e39, 0.0, -1e39}) d.push_back(v);
  const Result rd = s.run(d);
  CAPTURE(static_cast<int>(rd.status));
  CHECK((rd.status == Status::kOk || rd.status == Status::kNotEnoughFeatures));
}

TEST_CASE("georeferenced views at 1e6 and 1e7 m give the answer found near the origin") {
  Session s;
  const double origin[3] = {0.0, 0.0, 0.0};
  const double offsets[][3] = {
      {0.0, 0.0, 0.0}, {1.0e6, 2.0e6, 120.0}, {431000.5, 4020000.25, 87.0}, {-9.5e6, 9.9e6, 3000.0}};
  const Result near = s.run(known_query(origin));
  REQUIRE(near.status == Status::kOk);
  const uint32_t near_model = near.ranking[0].model;  // the ranking lives in the workspace: copy it
  for (const auto& o : offsets) {
    CAPTURE(o[1]);
    const Result far = s.run(known_query(o));
    REQUIRE(far.status == Status::kOk);
    CHECK(far.ranking[0].model == near_model);
    CHECK(far.confident == near.confident);
    // Recentring in double keeps the geometry, but last-bit differences in the
    // recentred floats may move a point across a voxel edge, so the sampled
    // hypotheses (not the answer) can differ: poses agree to RANSAC accuracy.
    constexpr double kPoseTolerance = 0.3;  // m, as in test_recognize.cpp
    for (int a = 0; a < 3; ++a) CHECK(std::fabs(far.ranking[0].pose.translation[a] - o[a]) < kPoseTolerance);
  }
}

TEST_CASE("a cloud above max_points is thinned deterministically, or refused when asked") {
  RecognizerConfig cfg = fast_config();
  constexpr uint32_t kMaxPoints = 1500;
  cfg.max_points = kMaxPoints;
  Session s(cfg);
  const std::vector<double> q = known_query();
  const uint32_t n = static_cast<uint32_t>(q.size() / 3);
  REQUIRE(n > kMaxPoints);
  const Result a = s.run(q);
  REQUIRE(a.status == Status::kOk);
  CHECK(a.stats.extract.points_thinned == n - kMaxPoints);
  CHECK(a.stats.extract.points_in == n);
  REQUIRE(a.ranking_count > 0);
  const uint32_t model = a.ranking[0].model;
  const float score = a.ranking[0].score;
  const Result b = s.run(q);
  REQUIRE(b.ranking_count > 0);
  CHECK(b.ranking[0].model == model);
  CHECK(b.ranking[0].score == score);
  CHECK(b.stats.extract.points_thinned == n - kMaxPoints);

  cfg.thin_large_clouds = false;
  Session refuse(cfg);
  const Result r = refuse.run(q);
  CHECK(r.status == Status::kTooManyPoints);
  CHECK(r.ranking_count == 0);
  std::vector<double> fits(q.begin(), q.begin() + 3 * kMaxPoints);  // exactly at the limit: accepted
  CHECK(refuse.run(fits).status == Status::kOk);
}

namespace {

// Points uniform in a cube of `side` m (deterministic generator).
std::vector<double> random_blob(uint32_t points, double side) {
  uint64_t state = 0x9E3779B97F4A7C15ull;
  std::vector<double> blob;
  for (uint32_t i = 0; i < 3 * points; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    blob.push_back(side * static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0));
  }
  return blob;
}

constexpr uint32_t kUnknownPoints = 3000;
constexpr float kSphereZ = 1.5f;  // m: centred at a toy's height

float mean_score(const Result& r) {
  return r.ranking[0].score / static_cast<float>(r.stats.extract.features);
}

}  // namespace

TEST_CASE("objects larger than every model (a 3 m sphere, a 3 m random blob) are not confident") {
  Session s;
  constexpr float kRadius = 3.0f;
  check_not_confident(s.run(test::fibonacci_sphere(kUnknownPoints, kRadius, 0.0f, 0.0f, kSphereZ)));
  constexpr double kSide = 3.0;
  check_not_confident(s.run(random_blob(kUnknownPoints, kSide)));
}

// An object smaller than a vehicle (a 1-1.5 m sphere, a 1 m blob) fits inside
// a model's surface for 30-60 % of its features, so the inlier share alone
// would call it confident; its log-likelihood per feature is far below a
// real view's, and `confident` also requires min_mean_log_likelihood.
TEST_CASE("objects smaller than the models are not confident where the scores say so") {
  Session s;
  const Result known = s.run(known_query());
  REQUIRE(known.status == Status::kOk);
  const float known_mean = mean_score(known);  // before the next run reuses the workspace
  constexpr float kScoreGap = 1.0f;  // per feature: the unknowns score this much below a real view at least
  std::vector<std::vector<double>> unknowns;
  for (float radius : {1.0f, 1.5f}) {
    std::vector<float> f = test::fibonacci_sphere(kUnknownPoints, radius, 0.0f, 0.0f, kSphereZ);
    unknowns.emplace_back(f.begin(), f.end());
  }
  constexpr double kSmallSide = 1.0;
  unknowns.push_back(random_blob(kUnknownPoints, kSmallSide));
  for (const std::vector<double>& cloud : unknowns) {
    const Result r = s.run(cloud);
    REQUIRE(r.status == Status::kOk);
    REQUIRE(r.ranking_count > 0);
    CHECK(mean_score(r) < known_mean - kScoreGap);  // the scores say so...
    CHECK_FALSE(r.confident);                       // ...and so does the flag
  }
}

TEST_CASE("a workspace below required_workspace_bytes is kWorkspaceTooSmall") {
  const RecognizerConfig cfg;
  const size_t need = required_workspace_bytes(cfg);
  REQUIRE(need > 0);
  host::AlignedBytes ws(need);
  Recognizer r;
  constexpr size_t kTiny = 64;
  for (size_t bytes : {size_t{0}, kTiny, need / 2, need - 2 * kBufferAlignment}) {
    CAPTURE(bytes);
    CHECK(r.init(&test::shared_toy_database().db, cfg, ws.data(), bytes) == Status::kWorkspaceTooSmall);
    CHECK(r.recognize(static_cast<const float*>(nullptr), 0).status == Status::kNotOpen);
  }
  CHECK(r.init(&test::shared_toy_database().db, cfg, ws.data(), need) == Status::kOk);
  CHECK(r.used_bytes() <= need);
}

TEST_CASE("a misaligned workspace is kMisalignedBuffer") {
  const RecognizerConfig cfg;
  const size_t need = required_workspace_bytes(cfg);
  host::AlignedBytes ws(need + kBufferAlignment);
  Recognizer r;
  for (size_t shift : {size_t{1}, size_t{4}, size_t{8}, size_t{32}}) {
    CAPTURE(shift);
    CHECK(r.init(&test::shared_toy_database().db, cfg, ws.data() + shift, need) == Status::kMisalignedBuffer);
  }
  CHECK(r.recognize(static_cast<const double*>(nullptr), 0).status == Status::kNotOpen);
}

TEST_CASE("null pointers are kInvalidArgument; a recognizer never initialised is kNotOpen") {
  const RecognizerConfig cfg;
  host::AlignedBytes ws(required_workspace_bytes(cfg));
  Recognizer r;
  CHECK(r.recognize(static_cast<const float*>(nullptr), 3).status == Status::kNotOpen);
  const double p[3] = {0, 0, 0};
  CHECK(r.recognize(p, 1).status == Status::kNotOpen);
  CHECK(r.init(nullptr, cfg, ws.data(), ws.size()) == Status::kInvalidArgument);
  const Database closed;  // never opened
  CHECK(r.init(&closed, cfg, ws.data(), ws.size()) == Status::kInvalidArgument);
  CHECK(r.init(&test::shared_toy_database().db, cfg, nullptr, ws.size()) == Status::kInvalidArgument);
  REQUIRE(r.init(&test::shared_toy_database().db, cfg, ws.data(), ws.size()) == Status::kOk);
  CHECK(r.recognize(static_cast<const float*>(nullptr), 3).status == Status::kInvalidArgument);
  CHECK(r.recognize(static_cast<const double*>(nullptr), 3).status == Status::kInvalidArgument);
}

TEST_CASE("invalid config values are refused by required_workspace_bytes and init") {
  struct Case {
    const char* what;
    void (*patch)(RecognizerConfig&);
  };
  const Case cases[] = {
      {"NaN sigma", [](RecognizerConfig& c) { c.draws.sigma = kNaN; }},
      {"zero sigma", [](RecognizerConfig& c) { c.draws.sigma = 0.0f; }},
      {"NaN delta", [](RecognizerConfig& c) { c.draws.delta = kNaN; }},
      {"delta_max below delta", [](RecognizerConfig& c) { c.draws.delta_max = c.draws.delta * 0.5f; }},
      {"infinite d_min", [](RecognizerConfig& c) { c.draws.d_min = kInf; }},
      {"negative distance tolerance", [](RecognizerConfig& c) { c.draws.tol_distance = -0.1f; }},
      {"NaN angle tolerance", [](RecognizerConfig& c) { c.draws.tol_angle_deg = kNaN; }},
      {"NaN handedness tolerance", [](RecognizerConfig& c) { c.draws.tol_handedness = kNaN; }},
      {"NaN theta_min", [](RecognizerConfig& c) { c.draws.theta_min_deg = kNaN; }},
      {"eta_max 181", [](RecognizerConfig& c) { c.draws.eta_max_deg = 181.0f; }},
      {"zero spin lambda", [](RecognizerConfig& c) { c.draws.spin_lambda = 0.0f; }},
      {"NaN min_inlier_fraction", [](RecognizerConfig& c) { c.confidence.min_inlier_fraction = kNaN; }},
      {"min_inlier_fraction 1.5", [](RecognizerConfig& c) { c.confidence.min_inlier_fraction = 1.5f; }},
      {"NaN min_mean_log_likelihood",
       [](RecognizerConfig& c) { c.confidence.min_mean_log_likelihood = kNaN; }},
      {"positive min_mean_log_likelihood",
       [](RecognizerConfig& c) { c.confidence.min_mean_log_likelihood = 1.0f; }},
      {"-inf min_mean_log_likelihood",
       [](RecognizerConfig& c) { c.confidence.min_mean_log_likelihood = -kInf; }},
      {"verify_features 0", [](RecognizerConfig& c) { c.draws.verify_features = 0; }},
      {"NaN query basis spacing", [](RecognizerConfig& c) { c.extract.query_basis_spacing = kNaN; }},
      {"negative query basis spacing", [](RecognizerConfig& c) { c.extract.query_basis_spacing = -1.0f; }},
      {"max_points 0", [](RecognizerConfig& c) { c.max_points = 0; }},
      {"max_points above the limit", [](RecognizerConfig& c) { c.max_points = kMaxQueryPointsLimit + 1u; }},
      {"max_features 1", [](RecognizerConfig& c) { c.max_features = 1; }},
      {"max_models 0", [](RecognizerConfig& c) { c.max_models = 0; }},
      {"max_spin_dims above the limit", [](RecognizerConfig& c) { c.max_spin_dims = kMaxSpinDims + 1u; }},
      {"top_w 0", [](RecognizerConfig& c) { c.candidates.top_w = 0; }},
      {"top_w above kMaxCandidates", [](RecognizerConfig& c) { c.candidates.top_w = kMaxCandidates + 1u; }},
      {"max_bucket_scan 0", [](RecognizerConfig& c) { c.candidates.max_bucket_scan = 0; }},
      {"NaN viewpoint",
       [](RecognizerConfig& c) {
         c.has_viewpoint = true;
         c.viewpoint[1] = std::numeric_limits<double>::quiet_NaN();
       }},
  };
  const RecognizerConfig good;
  host::AlignedBytes ws(required_workspace_bytes(good));
  for (const Case& k : cases) {
    CAPTURE(k.what);
    RecognizerConfig cfg;
    k.patch(cfg);
    CHECK(required_workspace_bytes(cfg) == 0);
    Recognizer r;
    CHECK(r.init(&test::shared_toy_database().db, cfg, ws.data(), ws.size()) == Status::kInvalidArgument);
  }
}

TEST_CASE("capacities below the database are refused at init") {
  RecognizerConfig few_models;
  few_models.max_models = test::kToyModels - 1u;
  host::AlignedBytes ws(required_workspace_bytes(few_models));
  Recognizer r;
  CHECK(r.init(&test::shared_toy_database().db, few_models, ws.data(), ws.size()) ==
        Status::kDatabaseTooLarge);
  RecognizerConfig small_spins;
  small_spins.max_spin_dims = test::shared_toy_database().db.spin_dims() - 1u;
  host::AlignedBytes ws2(required_workspace_bytes(small_spins));
  CHECK(r.init(&test::shared_toy_database().db, small_spins, ws2.data(), ws2.size()) ==
        Status::kInvalidArgument);
}

// A mode outside the enum (from the C API or a corrupt settings file) must
// not run as "no mode" and return an empty ranking with kOk.
TEST_CASE("a mode outside the enum is an invalid argument") {
  constexpr uint8_t kBadMode = 7;
  RecognizerConfig cfg;
  cfg.mode = static_cast<Mode>(kBadMode);
  CHECK(required_workspace_bytes(cfg) == 0);
  host::AlignedBytes ws(required_workspace_bytes(RecognizerConfig()));
  Recognizer r;
  CHECK(r.init(&test::shared_toy_database().db, cfg, ws.data(), ws.size()) == Status::kInvalidArgument);
}
