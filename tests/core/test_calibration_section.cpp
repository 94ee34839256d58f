// The Calibration section (docs/blob-format.md 5.8): a fitted table opens
// and reads back through Database::calibration(); every field corrupted on
// its own, the blob re-sealed, is refused with the status the format names.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "blob/blob_writer.hpp"
#include "db/tiny_blob.hpp"
#include "spinhash/calibration.hpp"
#include "support/blob_patch.hpp"

using spinhash::AnswerLevel;
using spinhash::AnswerPass;
using spinhash::Calibration;
using spinhash::Database;
using spinhash::kCalibratedLevels;
using spinhash::level_index;
using spinhash::Status;
using spinhash::test::BlobPatch;
namespace blob = spinhash::blob;
namespace host = spinhash::host;

namespace {

constexpr uint32_t kBands = 3;  // 0-20, 20-80, 80+ points per m^2
constexpr float kTarget = 0.95f;

blob::CalibrationCell fitted(float threshold, float precision, float recall) {
  blob::CalibrationCell c{};
  c.state = blob::kCellFitted;
  c.threshold = threshold;
  c.precision = precision;
  c.recall = recall;
  c.positives = 40;
  c.negatives = 10;
  c.flagged = 30;
  return c;
}

blob::CalibrationCell never(uint32_t state) {
  blob::CalibrationCell c{};
  c.state = state;
  c.positives = 3;
  c.negatives = 2;
  return c;
}

// Per level (vehicle, group, class, model), sparsest band first: the
// vehicle level fitted everywhere, the model level never in the sparsest.
host::CalibrationContent fitted_calibration() {
  host::CalibrationContent c;
  c.header.pass_count = 1;
  c.header.level_count = kCalibratedLevels;
  c.header.band_count = kBands;
  c.header.target_precision = kTarget;
  c.header.band_min_density[1] = 20.0f;
  c.header.band_min_density[2] = 80.0f;
  c.header.scans_per_model = 4;
  c.header.models_left_out = 3;
  c.header.clutter_scans = 8;
  c.header.seed = 0x0102030405060708ull;
  c.header.clutter = blob::kClutterVehicleSized;
  c.passes.push_back(blob::CalibrationPass{0u, blob::kSourceFitted, 40u, 0.0f});
  const blob::CalibrationCell cells[] = {
      fitted(-2.0f, 0.96f, 0.7f),    fitted(-2.5f, 0.97f, 0.8f),    fitted(-2.5f, 0.99f, 0.9f),   // vehicle
      never(blob::kCellUnreachable), fitted(1.5f, 0.95f, 0.5f),     fitted(1.0f, 1.0f, 0.75f),    // group
      never(blob::kCellTooFew),      fitted(2.0f, 0.96f, 0.4f),     fitted(2.0f, 0.98f, 0.6f),    // class
      never(blob::kCellTooFew),      never(blob::kCellUnreachable), fitted(3.0f, 0.995f, 0.85f),  // model
  };
  c.cells.assign(std::begin(cells), std::end(cells));
  return c;
}

const host::BlobContent& content() {
  static const host::BlobContent c = [] {
    host::BlobContent t = host::make_tiny_blob_content(3, 20, 11);
    t.calibration = fitted_calibration();
    return t;
  }();
  return c;
}

const std::vector<uint8_t>& fitted_blob() {
  static const std::vector<uint8_t> bytes = spinhash::test::write_native(content());
  return bytes;
}

blob::CalibrationHeader& header(BlobPatch& b) {
  return *b.section<blob::CalibrationHeader>(blob::kCalibration);
}
blob::CalibrationPass& pass(BlobPatch& b) {
  return *reinterpret_cast<blob::CalibrationPass*>(b.payload(blob::kCalibration) +
                                                   sizeof(blob::CalibrationHeader));
}
// Cell of `level` (1..4) in `band`.
blob::CalibrationCell& cell(BlobPatch& b, uint32_t level, uint32_t band) {
  uint8_t* cells =
      b.payload(blob::kCalibration) + sizeof(blob::CalibrationHeader) + sizeof(blob::CalibrationPass);
  return reinterpret_cast<blob::CalibrationCell*>(cells)[(level - 1u) * kBands + band];
}

// The section cut to `size` bytes, the bytes cut off zeroed (they become
// padding, which must be zero).
void shorten(BlobPatch& b, uint64_t size) {
  blob::SectionEntry& e = b.entry_of(blob::kCalibration);
  std::memset(b.data() + e.offset + size, 0, static_cast<size_t>(e.size - size));
  e.size = size;
}

struct Corruption {
  const char* what;
  void (*patch)(BlobPatch&);
};
template <size_t N>
void check_corruptions(const Corruption (&cases)[N], Status expected) {
  for (const Corruption& k : cases) {
    CAPTURE(k.what);
    BlobPatch b(fitted_blob());
    REQUIRE(b.open() == Status::kOk);
    k.patch(b);
    b.reseal();
    CHECK(b.open() == expected);
  }
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace

TEST_CASE(
    "a fitted calibration opens and reads back; its decision is evidence against the band's threshold") {
  BlobPatch b(fitted_blob());
  Database db;
  REQUIRE(b.open(&db) == Status::kOk);
  const Calibration& c = db.calibration();
  REQUIRE(c.present());
  CHECK(c.pass_count() == 1u);
  CHECK(c.band_count() == kBands);
  CHECK(c.fitted(AnswerPass::kFull));
  CHECK(c.header().seed == 0x0102030405060708ull);
  CHECK(c.band_of(0.0f) == 0u);
  CHECK(c.band_of(19.9f) == 0u);
  CHECK(c.band_of(20.0f) == 1u);
  CHECK(c.band_of(1e9f) == 2u);
  CHECK(c.band_of(kNaN) == 0u);
  CHECK(c.band_of(-5.0f) == 0u);
  const blob::CalibrationCell* group_dense = c.cell(AnswerPass::kFull, AnswerLevel::kGroup, 2);
  REQUIRE(group_dense != nullptr);
  CHECK(group_dense->threshold == 1.0f);
  CHECK(group_dense->recall == 0.75f);
  CHECK(c.cell(AnswerPass::kFull, AnswerLevel::kNone, 0) == nullptr);
  CHECK(c.cell(AnswerPass::kFull, AnswerLevel::kModel, kBands) == nullptr);
  // Fitted bands: at or above the threshold; never-confident bands: never.
  CHECK(c.confident(AnswerPass::kFull, AnswerLevel::kModel, 3.0f, 100.0f));
  CHECK_FALSE(c.confident(AnswerPass::kFull, AnswerLevel::kModel, 2.99f, 100.0f));
  CHECK_FALSE(c.confident(AnswerPass::kFull, AnswerLevel::kModel, 1e30f, 50.0f));
  CHECK(c.confident(AnswerPass::kFull, AnswerLevel::kModel, kInf, 100.0f));
  CHECK_FALSE(c.confident(AnswerPass::kFull, AnswerLevel::kModel, -kInf, 100.0f));
  CHECK_FALSE(c.confident(AnswerPass::kFull, AnswerLevel::kModel, kNaN, 100.0f));
  CHECK(c.confident(AnswerPass::kFull, AnswerLevel::kVehicle, -2.0f, 5.0f));
  CHECK_FALSE(c.confident(AnswerPass::kFull, AnswerLevel::kVehicle, -2.1f, 5.0f));
}

TEST_CASE("a blob without a fitted table holds the priors section: one pass, one band, all zero") {
  const std::vector<uint8_t> bytes = spinhash::test::write_native(host::make_tiny_blob_content(3, 20, 11));
  BlobPatch b(bytes);
  Database db;
  REQUIRE(b.open(&db) == Status::kOk);
  const Calibration& c = db.calibration();
  CHECK(c.present());
  CHECK_FALSE(c.fitted(AnswerPass::kFull));
  CHECK(c.band_count() == 1u);
  const blob::CalibrationCell* cell0 = c.cell(AnswerPass::kFull, AnswerLevel::kModel, 0);
  REQUIRE(cell0 != nullptr);
  CHECK(cell0->state == blob::kCellPriors);
  CHECK_FALSE(Calibration().present());
  CHECK_FALSE(Calibration().fitted(AnswerPass::kFull));
  CHECK(Calibration().cell(AnswerPass::kFull, AnswerLevel::kModel, 0) == nullptr);
}

TEST_CASE("the calibration is written in the blob's byte order, field by field") {
  std::vector<uint8_t> swapped;
  std::string error;
  REQUIRE(
      host::serialize_blob(content(), host::opposite_byte_order(host::ByteOrder::kNative), &swapped, &error));
  BlobPatch other(swapped), native(fitted_blob());
  REQUIRE(other.size() == native.size());
  const uint64_t offset = host::byteswap_scalar(other.entry(blob::kCalibration - 1u).offset);
  const uint64_t size = host::byteswap_scalar(other.entry(blob::kCalibration - 1u).size);
  REQUIRE(offset == native.entry_of(blob::kCalibration).offset);
  REQUIRE(size == native.entry_of(blob::kCalibration).size);
  // Every 4-byte scalar reversed; the 8-byte seed as one; reserved bytes zero either way.
  const uint8_t* a = other.data() + offset;
  const uint8_t* n = native.data() + offset;
  for (uint64_t at = 0; at < size; at += 4) {
    CAPTURE(at);
    if (at == offsetof(blob::CalibrationHeader, seed) || at == offsetof(blob::CalibrationHeader, seed) + 4u)
      continue;
    uint32_t x, y;
    std::memcpy(&x, a + at, 4);
    std::memcpy(&y, n + at, 4);
    CHECK(host::byteswap_scalar(x) == y);
  }
  uint64_t seed;
  std::memcpy(&seed, a + offsetof(blob::CalibrationHeader, seed), 8);
  CHECK(host::byteswap_scalar(seed) == 0x0102030405060708ull);
}

TEST_CASE("calibration counts that change the section's size are kBlobSizeMismatch") {
  const Corruption cases[] = {
      {"a second pass", [](BlobPatch& b) { header(b).pass_count = 2; }},
      {"a fourth band", [](BlobPatch& b) { header(b).band_count = 4; }},
      {"two bands", [](BlobPatch& b) { header(b).band_count = 2; }},
      {"a section shorter than its header",
       [](BlobPatch& b) { shorten(b, sizeof(blob::CalibrationHeader) - 4u); }},
      {"a section without its last cell",
       [](BlobPatch& b) { shorten(b, b.entry_of(blob::kCalibration).size - sizeof(blob::CalibrationCell)); }},
  };
  check_corruptions(cases, Status::kBlobSizeMismatch);
}

TEST_CASE("calibration counts, bands, passes and cells out of their rules are kBlobBadCalibration") {
  const Corruption cases[] = {
      {"no pass", [](BlobPatch& b) { header(b).pass_count = 0; }},
      {"more passes than the section holds",
       [](BlobPatch& b) { header(b).pass_count = blob::kMaxCalibrationPasses + 1u; }},
      {"three levels", [](BlobPatch& b) { header(b).level_count = 3; }},
      {"no band", [](BlobPatch& b) { header(b).band_count = 0; }},
      {"more bands than the header holds",
       [](BlobPatch& b) { header(b).band_count = blob::kMaxDensityBands + 1u; }},
      {"target precision NaN", [](BlobPatch& b) { header(b).target_precision = kNaN; }},
      {"target precision 0", [](BlobPatch& b) { header(b).target_precision = 0.0f; }},
      {"target precision above 1", [](BlobPatch& b) { header(b).target_precision = 1.5f; }},
      {"first band not from 0", [](BlobPatch& b) { header(b).band_min_density[0] = 1.0f; }},
      {"a band edge NaN", [](BlobPatch& b) { header(b).band_min_density[1] = kNaN; }},
      {"a band edge infinite", [](BlobPatch& b) { header(b).band_min_density[2] = kInf; }},
      {"band edges not increasing", [](BlobPatch& b) { header(b).band_min_density[2] = 20.0f; }},
      {"clutter of no known kinds",
       [](BlobPatch& b) { header(b).clutter = blob::kClutterVehicleSized + 1u; }},
      {"a pass of another id", [](BlobPatch& b) { pass(b).pass = 1; }},
      {"a pass of no known source", [](BlobPatch& b) { pass(b).source = 2; }},
      {"a pass's own target NaN", [](BlobPatch& b) { pass(b).target_precision = kNaN; }},
      {"a pass's own target negative", [](BlobPatch& b) { pass(b).target_precision = -0.5f; }},
      {"a pass's own target above 1", [](BlobPatch& b) { pass(b).target_precision = 1.5f; }},
      {"a pass's own target above a fitted cell's precision",
       [](BlobPatch& b) { pass(b).target_precision = 0.999f; }},
      {"a priors pass that counts runs",
       [](BlobPatch& b) {
         pass(b).source = blob::kSourcePriors;  // its cells are not zero either; the runs come first
       }},
      {"a threshold NaN", [](BlobPatch& b) { cell(b, 1, 0).threshold = kNaN; }},
      {"a threshold infinite", [](BlobPatch& b) { cell(b, 4, 2).threshold = kInf; }},
      {"a precision above 1", [](BlobPatch& b) { cell(b, 2, 1).precision = 1.5f; }},
      {"a precision NaN", [](BlobPatch& b) { cell(b, 2, 1).precision = kNaN; }},
      {"a recall below 0", [](BlobPatch& b) { cell(b, 3, 2).recall = -0.1f; }},
      {"more flagged than runs", [](BlobPatch& b) { cell(b, 1, 1).flagged = 51; }},
      {"a state of no meaning", [](BlobPatch& b) { cell(b, 1, 1).state = 7; }},
      {"a priors state in a fitted table", [](BlobPatch& b) { cell(b, 1, 1).state = blob::kCellPriors; }},
      {"a fitted precision under the target", [](BlobPatch& b) { cell(b, 3, 1).precision = 0.9f; }},
      {"a never-confident band with a threshold", [](BlobPatch& b) { cell(b, 4, 0).threshold = 1.0f; }},
      {"a never-confident band that flags", [](BlobPatch& b) { cell(b, 4, 1).flagged = 1; }},
      {"a denser band needing more evidence", [](BlobPatch& b) { cell(b, 2, 2).threshold = 2.0f; }},
      {"a denser band never confident after a fitted one",
       [](BlobPatch& b) {
         cell(b, 3, 2) = blob::CalibrationCell{};
         cell(b, 3, 2).state = blob::kCellUnreachable;
       }},
  };
  check_corruptions(cases, Status::kBlobBadCalibration);
}

TEST_CASE("a priors pass with anything in its cells is kBlobBadCalibration") {
  host::BlobContent c = host::make_tiny_blob_content(3, 20, 11);
  const std::vector<uint8_t> bytes = spinhash::test::write_native(c);
  REQUIRE(BlobPatch(bytes).open() == Status::kOk);
  for (size_t at = 0; at < kCalibratedLevels * sizeof(blob::CalibrationCell); ++at) {
    if (at % sizeof(blob::CalibrationCell) >= offsetof(blob::CalibrationCell, reserved))
      continue;  // not zeroed
    BlobPatch p(bytes);
    p.payload(blob::kCalibration)[sizeof(blob::CalibrationHeader) + sizeof(blob::CalibrationPass) + at] = 1;
    p.reseal();
    CAPTURE(at);
    CHECK(p.open() == Status::kBlobBadCalibration);
  }
  BlobPatch runs(bytes);
  pass(runs).runs = 5;
  runs.reseal();
  CHECK(runs.open() == Status::kBlobBadCalibration);
  BlobPatch target(bytes);
  pass(target).target_precision = 0.99f;
  target.reseal();
  CHECK(target.open() == Status::kBlobBadCalibration);
}

TEST_CASE("a pass's own target replaces the header's: its cells reach it, not the header's") {
  Database db;
  BlobPatch header_target(fitted_blob());
  REQUIRE(header_target.open(&db) == Status::kOk);
  CHECK(db.calibration().target_precision(AnswerPass::kFull) == kTarget);
  CHECK(db.calibration().target_precision(AnswerPass::kFirst) == 0.0f);  // no such pass in the section
  // The header asks more than the cells reach; the pass's own target, what they do.
  BlobPatch own(fitted_blob());
  header(own).target_precision = 0.999f;
  pass(own).target_precision = kTarget;
  own.reseal();
  REQUIRE(own.open(&db) == Status::kOk);
  CHECK(db.calibration().target_precision(AnswerPass::kFull) == kTarget);
  BlobPatch header_only(fitted_blob());
  header(header_only).target_precision = 0.999f;
  header_only.reseal();
  CHECK(header_only.open() == Status::kBlobBadCalibration);
}

TEST_CASE("non-zero reserved calibration bytes and unused band edges are kBlobNotZeroed") {
  const Corruption cases[] = {
      {"header reserved, last byte",
       [](BlobPatch& b) { header(b).reserved[sizeof(blob::CalibrationHeader::reserved) - 1u] = 1; }},
      {"an unused band edge", [](BlobPatch& b) { header(b).band_min_density[kBands] = 500.0f; }},
      {"cell reserved", [](BlobPatch& b) { cell(b, 4, 2).reserved = 0x80000000u; }},
  };
  check_corruptions(cases, Status::kBlobNotZeroed);
}

TEST_CASE("level and pass names parse back; others do not") {
  for (uint32_t id = 0; id < spinhash::kAnswerLevelCount; ++id) {
    AnswerLevel l{};
    CHECK(spinhash::parse_answer_level(spinhash::answer_level_name(id), &l));
    CHECK(static_cast<uint32_t>(l) == id);
  }
  CHECK(std::string(spinhash::answer_level_name(static_cast<uint32_t>(AnswerLevel::kModel))) == "model");
  CHECK(std::string(spinhash::answer_level_name(spinhash::kAnswerLevelCount)) == "unknown");
  CHECK(std::string(spinhash::answer_pass_name(0)) == "full");
  CHECK_FALSE(spinhash::parse_answer_level("Model", nullptr));
  CHECK_FALSE(spinhash::parse_answer_level(nullptr, nullptr));
  CHECK(level_index(AnswerLevel::kVehicle) == 0u);
  CHECK(level_index(AnswerLevel::kModel) == kCalibratedLevels - 1u);
}
