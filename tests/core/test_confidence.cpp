// What `confident` promises (recognize/confidence.cpp): besides a fit and a
// margin, a scan that shows the model's whole extent. A scan whose end is
// hidden is explained as well by a longer look-alike, so its answer, even
// when right, is not confident.
#include <doctest/doctest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "recognize/confidence.hpp"
#include "spinhash/presets.hpp"
#include "spinhash/recognizer.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

// A 4 x 2 x 1.5 m box standing on z = 0, centred on x and y, its surface at 0.1 m.
constexpr float kLength = 4.0f, kWidth = 2.0f, kHeight = 1.5f, kSpacing = 0.1f;
constexpr float kTolerance = 1e-4f;    // m: float rounding of the fit
constexpr float kNeverShort = 1e6f;    // m: a max_extent_shortfall that never withholds confidence
constexpr float kAnyResidualF = 1e6f;  // a max_residual_f that never withholds confidence

blob::ModelRecord box_record() {
  blob::ModelRecord rec{};
  const float half[3] = {0.5f * kLength, 0.5f * kWidth, 0.0f};
  for (int a = 0; a < 2; ++a) rec.bbox_min[a] = -half[a], rec.bbox_max[a] = half[a];
  rec.bbox_min[2] = 0.0f;
  rec.bbox_max[2] = kHeight;
  return rec;
}

std::vector<float> box_points() {
  std::vector<float> p = test::box_surface(kLength, kWidth, kHeight, kSpacing);
  for (size_t i = 2; i < p.size(); i += 3) p[i] += 0.5f * kHeight;  // box_surface is centred
  return p;
}

ExtentFit fit_of(const std::vector<float>& points, const RigidPose& pose) {
  QueryFeatures q;
  q.positions = points.data();
  q.count = static_cast<uint32_t>(points.size() / 3);
  return extent_fit(q, box_record(), pose);
}

RigidPose identity() {
  RigidPose p;
  p.rotation.setIdentity();
  p.translation.setZero();
  return p;
}

// A posed first model that explains the query well and leads a runner-up
// by `margins` x min_margin x sqrt(features): only the margin's factors
// (coverage, density, spread) decide whether it is confident.
struct LeadingAnswer {
  RankedModel ranking[2];
  Result r;
  LeadingAnswer(const RecognizerConfig& cfg, uint32_t features, float margins) {
    ranking[0].has_pose = true;
    ranking[0].inliers = 3u * features / 4u;
    ranking[0].score = -1.5f * static_cast<float>(features);
    ranking[1].score =
        ranking[0].score - margins * cfg.confidence.min_margin * std::sqrt(static_cast<float>(features));
    r.ranking = ranking;
    r.ranking_count = 2;
    r.group_size = 1;
  }
};

}  // namespace

TEST_CASE(
    "extent fit: a whole box is pinned, a cut one falls short, a shifted one overhangs, a stray feature does "
    "not") {
  const std::vector<float> box = box_points();
  const ExtentFit whole = fit_of(box, identity());
  CHECK(whole.shortfall <= kTolerance);
  CHECK(whole.overhang <= kTolerance);

  // The front 1.5 m hidden: the query stops 1.5 m short of the box's front.
  const ExtentFit cut = fit_of(
      test::filtered(box, [](float x, float, float) { return x <= 0.5f * kLength - 1.5f; }), identity());
  CHECK(cut.shortfall == doctest::Approx(1.5f).epsilon(0.01));
  CHECK(cut.overhang <= kTolerance);

  // The top hidden (a lower look-alike would fit): short by the part's height.
  const ExtentFit low =
      fit_of(test::filtered(box, [](float, float, float z) { return z <= kHeight - 0.6f; }), identity());
  CHECK(low.shortfall == doctest::Approx(0.6f).epsilon(0.01));

  // The bottom is not tested: terrain removal cuts it.
  const ExtentFit raised =
      fit_of(test::filtered(box, [](float, float, float z) { return z >= 0.5f; }), identity());
  CHECK(raised.shortfall <= kTolerance);

  // One stray feature 0.6 m above the roof (a noise spike) is not an
  // overhang; two are.
  std::vector<float> stray = box;
  stray.insert(stray.end(), {0.0f, 0.0f, kHeight + 0.6f});
  CHECK(fit_of(stray, identity()).overhang <= kTolerance);
  stray.insert(stray.end(), {0.5f, 0.0f, kHeight + 0.6f});
  CHECK(fit_of(stray, identity()).overhang == doctest::Approx(0.6f).epsilon(0.01));
  CHECK(fit_of(stray, identity()).shortfall <= kTolerance);

  // A pose 0.4 m off along y: the query reaches 0.4 m past one side and
  // stops 0.4 m short of the other.
  RigidPose off = identity();
  off.translation = Eigen::Vector3f(0.0f, -0.4f, 0.0f);
  const ExtentFit shifted = fit_of(box, off);
  CHECK(shifted.shortfall == doctest::Approx(0.4f).epsilon(0.01));
  CHECK(shifted.overhang == doctest::Approx(0.4f).epsilon(0.01));
}

TEST_CASE("extent fit is measured in the model's frame: the pose's rotation is undone") {
  const std::vector<float> box = box_points();
  RigidPose quarter = identity();  // model x -> query y
  quarter.rotation << 0.0f, -1.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f;
  quarter.translation = Eigen::Vector3f(10.0f, -3.0f, 2.0f);
  std::vector<float> turned(box.size());
  for (size_t i = 0; i < box.size(); i += 3) {
    const Eigen::Vector3f q =
        quarter.rotation * Eigen::Vector3f(box[i], box[i + 1], box[i + 2]) + quarter.translation;
    for (int a = 0; a < 3; ++a) turned[i + static_cast<size_t>(a)] = q[a];
  }
  const ExtentFit fit = fit_of(turned, quarter);
  CHECK(fit.shortfall <= 1e-3f);
  CHECK(fit.overhang <= 1e-3f);
  CHECK(fit_of(turned, identity()).overhang >= 1.0f);  // the same points under the wrong pose
}

TEST_CASE("confident needs every gate: fit, score, a group of one, and the scan's extent") {
  const RecognizerConfig cfg;
  constexpr uint32_t kFeatures = 400;
  RankedModel first;
  first.has_pose = true;
  first.inliers = 300;    // 75 % of the features explained
  first.score = -600.0f;  // -1.5 per feature
  Result r;
  r.ranking = &first;
  r.ranking_count = 1;
  r.group_size = 1;
  r.stats.confidence.surface_coverage = 1.0f;  // the whole top seen
  const ExtentFit pinned{0.05f, 0.05f};
  constexpr float kNoiseOnlyF = 1.0f;  // residual F of a scan that is the model plus noise
  CHECK(is_confident(r, cfg, kFeatures, pinned, kNoiseOnlyF));
  CHECK_FALSE(is_confident(r, cfg, kFeatures, pinned,
                           cfg.confidence.max_residual_f + 0.5f));  // a patch off the surface

  // The same answer with one thing changed.
  auto with = [&](auto change) {
    RankedModel m = first;
    Result changed = r;
    changed.ranking = &m;
    ExtentFit fit = pinned;
    change(changed, m, fit);
    return is_confident(changed, cfg, kFeatures, fit, kNoiseOnlyF);
  };
  CHECK_FALSE(with([](Result&, RankedModel& m, ExtentFit&) { m.has_pose = false; }));
  CHECK_FALSE(with([](Result&, RankedModel& m, ExtentFit&) { m.inliers = 90; }));      // < 25 %
  CHECK_FALSE(with([](Result&, RankedModel& m, ExtentFit&) { m.score = -1400.0f; }));  // < -3 per feature
  CHECK_FALSE(
      with([](Result& c, RankedModel&, ExtentFit&) { c.group_size = 2; }));  // a look-alike within the margin
  CHECK_FALSE(with([](Result& c, RankedModel&, ExtentFit&) { c.ranking_count = 0; }));
  CHECK_FALSE(with([&](Result&, RankedModel&, ExtentFit& f) {
    f.shortfall = cfg.confidence.max_extent_shortfall + 0.05f;
  }));
  CHECK_FALSE(with(
      [&](Result&, RankedModel&, ExtentFit& f) { f.overhang = cfg.confidence.max_extent_overhang + 0.05f; }));
  CHECK(with([&](Result&, RankedModel&, ExtentFit& f) {
    f.shortfall = cfg.confidence.max_extent_shortfall - 0.05f;
  }));
}

TEST_CASE("among many look-alikes the runner-up must trail by twice the margin") {
  const RecognizerConfig cfg;
  constexpr uint32_t kFeatures = 400;
  const float margin =
      cfg.confidence.min_margin * std::sqrt(static_cast<float>(kFeatures));  // log-likelihood
  RankedModel ranking[2];
  ranking[0].score = -600.0f;
  Result r;
  r.ranking = ranking;
  r.ranking_count = 2;
  for (float lead : {0.5f, 1.5f, 2.5f}) {  // in margins
    CAPTURE(lead);
    ranking[1].score = ranking[0].score - lead * margin;
    r.stats.candidates.spread = false;
    CHECK(lookalike_group_size(r, cfg, kFeatures) == (lead < 1.0f ? 2u : 1u));
    r.stats.candidates.spread = true;  // the runner-up is the best of many near-identical models
    CHECK(lookalike_group_size(r, cfg, kFeatures) == (lead < 2.0f ? 2u : 1u));
  }
}

TEST_CASE("a scan that shows less of the model's top needs a larger lead") {
  RecognizerConfig cfg;
  constexpr uint32_t kFeatures = 400;
  LeadingAnswer a(cfg, kFeatures, 1.5f);  // leads by 1.5 margins
  Result& r = a.r;
  RankedModel* ranking = a.ranking;
  const float margin =
      cfg.confidence.min_margin * std::sqrt(static_cast<float>(kFeatures));  // log-likelihood
  const ExtentFit pinned{0.05f, 0.05f};
  auto confident_at = [&](float coverage) {
    r.stats.confidence.surface_coverage = coverage;
    return is_confident(r, cfg, kFeatures, pinned, 1.0f);
  };
  CHECK(confident_at(1.0f));
  CHECK(confident_at(cfg.confidence.full_coverage));  // the plain margin down to full_coverage
  CHECK(confident_at(0.8f));                          // (0.9 / 0.8)^2 = 1.27 margins
  CHECK_FALSE(confident_at(0.7f));  // 1.65 margins: an occluder may hide what tells them apart
  CHECK_FALSE(confident_at(0.0f));  // nothing of the top seen: no lead is enough
  CHECK(confident_margin(r, cfg) > 1e30f);
  r.stats.confidence.surface_coverage = 0.45f;
  CHECK(confident_margin(r, cfg) == doctest::Approx(4.0f * cfg.confidence.min_margin));
  r.stats.candidates.spread = true;  // on top of the look-alikes' doubled margin
  CHECK(confident_margin(r, cfg) == doctest::Approx(8.0f * cfg.confidence.min_margin));
  r.stats.candidates.spread = false;
  cfg.confidence.full_coverage = 0.0f;  // off: the plain margin whatever the scan shows
  CHECK(confident_at(0.7f));
  CHECK(confident_margin(r, cfg) == doctest::Approx(cfg.confidence.min_margin));
  cfg.confidence.full_coverage = 0.9f;
  ranking[1].score = ranking[0].score - 2.0f * margin;
  CHECK(confident_at(0.7f));  // a lead of 2 margins is enough at 0.7
  r.ranking_count = 1;        // no runner-up: nothing to lead
  CHECK(confident_at(0.5f));
}

TEST_CASE("a sparser scan needs a larger lead: the margin grows as 1 / sqrt(density)") {
  RecognizerConfig cfg;
  constexpr uint32_t kFeatures = 200;
  LeadingAnswer a(cfg, kFeatures, 1.3f);  // leads by 1.3 margins
  Result& r = a.r;
  r.stats.confidence.surface_coverage = 1.0f;
  const ExtentFit pinned{0.05f, 0.05f};
  auto confident_at = [&](float density) {
    r.stats.confidence.scan_density = density;
    return is_confident(r, cfg, kFeatures, pinned, 1.0f);
  };
  CHECK(confident_at(1000.0f));                            // 0.05 m
  CHECK(confident_at(cfg.confidence.full_model_density));  // the plain margin down to where it was set
  CHECK(confident_at(90.0f));                              // sqrt(130 / 90) = 1.20 margins
  CHECK_FALSE(confident_at(64.0f));                        // 0.15 m, 40 % occluded: 1.43 margins
  r.stats.confidence.scan_density = 0.25f * cfg.confidence.full_model_density;
  CHECK(confident_margin(r, cfg) == doctest::Approx(2.0f * cfg.confidence.min_margin));
  r.stats.confidence.surface_coverage = 0.45f;  // times the coverage's (0.9 / 0.45)^2
  CHECK(confident_margin(r, cfg) == doctest::Approx(8.0f * cfg.confidence.min_margin));
  r.stats.confidence.scan_density = 0.0f;  // not measured: no factor
  CHECK(confident_margin(r, cfg) == doctest::Approx(4.0f * cfg.confidence.min_margin));
}

TEST_CASE("among many look-alikes the residuals must be closer to noise") {
  RecognizerConfig cfg;
  constexpr uint32_t kFeatures = 400;
  RankedModel first;
  first.has_pose = true;
  first.inliers = 300;
  first.score = -600.0f;
  Result r;
  r.ranking = &first;
  r.ranking_count = 1;
  r.group_size = 1;
  r.stats.confidence.surface_coverage = 1.0f;
  const ExtentFit pinned{0.05f, 0.05f};
  const float weak_shape = 0.9f * cfg.confidence.max_residual_f;  // a patch a little off the surface
  CHECK(is_confident(r, cfg, kFeatures, pinned, weak_shape));
  r.stats.candidates.spread = true;  // the first is one of many near-identical models
  CHECK(residual_limit(r, cfg) < weak_shape);
  CHECK_FALSE(is_confident(r, cfg, kFeatures, pinned, weak_shape));
  CHECK(is_confident(r, cfg, kFeatures, pinned, 1.0f));  // noise alone stays confident
  cfg.confidence.max_residual_f = 2.0f * weak_shape;     // the limit follows the configured field
  CHECK(is_confident(r, cfg, kFeatures, pinned, weak_shape));
}

TEST_CASE("a scan that hides a toy's end is not confident, though the right toy explains it best") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  constexpr uint32_t kModel = 0;       // toy-0: hull 4.5 m long, x in [-2.25, 2.25]
  constexpr double kHiddenFrom = 1.0;  // m: the hood beyond this is hidden (a tree)
  const std::vector<double> model = test::toy_vehicle_points(kModel, 0.05f);
  const std::vector<double> front_hidden =
      test::filtered(model, [&](double x, double, double) { return x <= kHiddenFrom; });
  const double t[3] = {-300.0, 80.0, 5.0};
  auto run = [&](const std::vector<double>& points, float shortfall, float residual_f = kAnyResidualF) {
    RecognizerConfig cfg;
    cfg.confidence.max_extent_shortfall = shortfall;
    cfg.confidence.max_residual_f = residual_f;
    host::AlignedBytes ws(required_workspace_bytes(cfg));
    Recognizer r;
    REQUIRE(r.init(&toy.db, cfg, ws.data(), ws.size()) == Status::kOk);
    const std::vector<double> q = test::toy_airborne_query(points, 0.4, t, 0.02, 7);
    const Result res = r.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
    REQUIRE(res.status == Status::kOk);
    REQUIRE(res.ranking_count > 0);
    return std::make_pair(res.ranking[0].model, res.confident);
  };
  const float defaults = RecognizerConfig{}.confidence.max_extent_shortfall;
  const auto whole = run(model, defaults);
  CHECK(whole.first == kModel);  // the whole top seen: right and confident
  CHECK(whole.second);
  // 1.25 m of the hood unseen: toy-0 still comes first, well ahead of the
  // 3.8 m toy-5 (with normals turned away from the centroid, toy-5 did),
  // and margin and fit alone would call it confident. But a scan that stops
  // 1.25 m short of the model's end cannot tell it from a shorter vehicle:
  // the extent test withholds it.
  const auto hidden = run(front_hidden, defaults);
  CHECK(hidden.first == kModel);
  CHECK_FALSE(hidden.second);
  // Without the extent test it is confident: the residuals of the right
  // toy are noise (the wrong toy's shape: the near-twin case below).
  CHECK(run(front_hidden, kNeverShort, RecognizerConfig{}.confidence.max_residual_f).second);
}

TEST_CASE("a near twin outside the database is not confident: its residuals are a shape, not noise") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  constexpr uint32_t kModel = 0;     // toy-0: hull 4.5 m long
  constexpr double kStretch = 1.04;  // the twin: 0.18 m longer, ends 9 cm off once centred
  constexpr double kNoise = 0.02;    // m, along the rays
  const double t[3] = {-300.0, 80.0, 5.0};
  // The full pass's residual test: at the cascade's first-pass voxel
  // (0.18 m) a 9 cm twin's residuals are noise.
  auto run = [&](double stretch, float residual_f) {
    std::vector<double> model = test::toy_vehicle_points(kModel, 0.05f);
    for (size_t i = 0; i < model.size(); i += 3) model[i] *= stretch;
    RecognizerConfig cfg = preset_config(Preset::kFull);
    cfg.confidence.max_residual_f = residual_f;
    host::AlignedBytes ws(required_workspace_bytes(cfg));
    Recognizer r;
    REQUIRE(r.init(&toy.db, cfg, ws.data(), ws.size()) == Status::kOk);
    const std::vector<double> q = test::toy_airborne_query(model, 0.4, t, kNoise, 7);
    const Result res = r.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
    REQUIRE(res.status == Status::kOk);
    REQUIRE(res.ranking_count > 0);
    return std::make_pair(res.ranking[0].model, res.confident);
  };
  const float defaults = RecognizerConfig{}.confidence.max_residual_f;
  const auto own = run(1.0, defaults);
  CHECK(own.first == kModel);  // the toy itself, plus noise: confident
  CHECK(own.second);
  const auto twin = run(kStretch, kAnyResidualF);
  CHECK(twin.first == kModel);  // the twin is named as its nearest toy ...
  CHECK(twin.second);           // ... and every other test would call it confident
  CHECK_FALSE(run(kStretch, defaults).second);
}

TEST_CASE("within a look-alike group the model whose residuals are noise comes first") {
  // toy-0 and a copy 4 % longer (0.18 m): a margin that holds every model
  // in the group leaves their order to the residuals alone.
  constexpr double kStretch = 1.04;
  std::vector<double> longer = test::toy_vehicle_points(0, 0.05f);
  for (size_t i = 0; i < longer.size(); i += 3) longer[i] *= kStretch;
  const std::vector<host::ModelCloud> clouds = {{"toy-0", test::toy_vehicle_points(0, 0.05f)},
                                                {"toy-0-long", longer}};
  test::ToyDatabase twins;
  REQUIRE(test::make_database(clouds, &twins));
  const double t[3] = {-300.0, 80.0, 5.0};
  auto first = [&](uint32_t scanned) {
    RecognizerConfig cfg;
    cfg.confidence.min_margin = 1e6f;  // every model within the margin: one group
    host::AlignedBytes ws(required_workspace_bytes(cfg));
    Recognizer r;
    REQUIRE(r.init(&twins.db, cfg, ws.data(), ws.size()) == Status::kOk);
    const std::vector<double> q = test::toy_airborne_query(clouds[scanned].xyz, 0.4, t, 0.02, 7);
    const Result res = r.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
    REQUIRE(res.status == Status::kOk);
    REQUIRE(res.ranking_count == 2u);
    CHECK(res.group_size == 2u);
    CHECK_FALSE(res.confident);  // a group is never confident
    return res.ranking[0].model;
  };
  CHECK(first(0) == 0u);
  CHECK(first(1) == 1u);
}

TEST_CASE("hidden ends: the removed ground band hides a low nose, and the shortfall there counts beyond it") {
  // A 4 x 2 x 1.2 m body on z = 0 with a 0.6 m long, 0.15 m high splitter
  // ahead of its front (+x): below a 0.25 m ground band, so a scan with its
  // ground removed never shows it.
  constexpr float kNose = 0.6f, kNoseHeight = 0.15f, kBand = 0.25f;
  std::vector<float> body = test::box_surface(kLength, kWidth, 1.2f, kSpacing);
  for (size_t i = 2; i < body.size(); i += 3) body[i] += 0.6f;
  std::vector<double> cloud(body.begin(), body.end());
  for (float x = 0.5f * kLength; x <= 0.5f * kLength + kNose; x += 0.5f * kSpacing)
    for (float y = -0.5f * kWidth; y <= 0.5f * kWidth; y += 0.5f * kSpacing)
      for (const float z : {0.0f, kNoseHeight}) cloud.insert(cloud.end(), {x, y, z});
  test::ToyDatabase t;
  REQUIRE(test::make_database({host::ModelCloud{"nosed", cloud, VehicleClass::kSedan}}, &t));
  const blob::ModelRecord& rec = t.db.model(0);

  const HiddenEnds none = hidden_ends(t.db, 0, 0.0f);
  for (const float f : none.face) CHECK(f == 0.0f);
  const HiddenEnds cut = hidden_ends(t.db, 0, kBand);
  CHECK(cut.face[1] > kNose - 2.0f * 0.25f);  // the front, within the features' spacing
  CHECK(cut.face[1] < kNose + 0.25f);
  CHECK(cut.face[0] < 0.25f);  // the back, the sides: the body reaches them above the band
  CHECK(cut.face[2] < 0.25f);
  CHECK(cut.face[3] < 0.25f);

  // A scan of the model above the band: short of the box's front by the
  // nose without the allowance, pinned with it.
  std::vector<float> above;
  const float* p = t.db.positions() + 3u * rec.first_feature;
  for (uint32_t f = 0; f < rec.feature_count; ++f)
    if (p[3u * f + 2u] > rec.bbox_min[2] + kBand) above.insert(above.end(), p + 3u * f, p + 3u * f + 3u);
  QueryFeatures q;
  q.positions = above.data();
  q.count = static_cast<uint32_t>(above.size() / 3);
  CHECK(extent_fit(q, rec, identity()).shortfall > kNose - 0.25f);
  CHECK(extent_fit(q, rec, identity(), cut).shortfall < 0.2f);
  CHECK(extent_fit(q, rec, identity(), cut).overhang == extent_fit(q, rec, identity()).overhang);
}
