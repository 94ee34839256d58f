// Recognizer::recognize on arbitrary points over toy vehicles of the core
// tests (database built once at start-up). Input: one control byte, then the points.
// Control bits 0-1 choose how the bytes become points, so the fuzzer reaches
// both hostile floats and plausible geometry:
//   0 raw float32 xyz (NaN, inf, 1e38...)     1 int16 xyz in cm near the origin
//   2 int16 xyz in cm at a UTM-like offset    3 raw float64 xyz (double API)
// bits 2-3: mode (BRAN, SRAN, SIND; 3 = BRAN), bit 4: refuse instead of
// thinning clouds above max_points.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "blob/blob_writer.hpp"
#include "db/database_builder.hpp"
#include "fuzz_support.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr double kCentimetre = 0.01;
constexpr double kUtmOffset[3] = {431000.5, 4020000.25, 87.0};
constexpr uint32_t kModeCount = 3;
constexpr uint32_t kThinChoices = 2;

// A smaller database than the core tests' toy one: half the models, sparser
// model clouds, so that start-up under ASan stays at a few seconds.
constexpr uint32_t kFuzzModels[] = {0, 2, 3};
constexpr float kModelSpacing = 0.08f;  // m

bool make_database(test::ToyDatabase* out) {
  std::vector<host::ModelCloud> clouds;
  for (uint32_t i : kFuzzModels)
    clouds.push_back(host::ModelCloud{"toy-" + std::to_string(i), test::toy_vehicle_points(i, kModelSpacing),
                                      test::toy_class(i)});
  host::BlobContent content;
  host::BuildReport report;
  std::vector<uint8_t> bytes;
  std::string error;
  if (!host::build_database(clouds, host::BuildOptions(), &content, &report, &error) ||
      !host::serialize_blob(content, host::ByteOrder::kNative, &bytes, &error))
    return false;
  out->bytes = host::AlignedBytes::copy_of(bytes);
  return Database::open(out->bytes.data(), out->bytes.size(), &out->db) == Status::kOk;
}

struct Fixture {
  test::ToyDatabase toy;
  fuzz::Session sessions[kModeCount * kThinChoices];
  bool ok = false;
  Fixture() {
    if (!make_database(&toy)) return;
    for (uint32_t i = 0; i < kModeCount * kThinChoices; ++i) {
      RecognizerConfig cfg = fuzz::small_config(static_cast<Mode>(i % kModeCount));
      cfg.thin_large_clouds = i < kModeCount;
      if (sessions[i].init(&toy.db, cfg) != Status::kOk) return;
    }
    ok = true;
  }
};

Fixture* fixture = nullptr;

template <typename T>
std::vector<T> raw_triples(const uint8_t* data, size_t size) {
  std::vector<T> v(size / (3 * sizeof(T)) * 3);
  if (!v.empty()) std::memcpy(v.data(), data, v.size() * sizeof(T));  // memcpy(nullptr, ...) is UB
  return v;
}

std::vector<double> centimetre_triples(const uint8_t* data, size_t size, const double offset[3]) {
  std::vector<int16_t> cm = raw_triples<int16_t>(data, size);
  std::vector<double> v(cm.size());
  for (size_t i = 0; i < cm.size(); ++i) v[i] = offset[i % 3] + cm[i] * kCentimetre;
  return v;
}

}  // namespace

// Set-up outside the per-input timeout.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fixture = new Fixture();
  fuzz::require(fixture->ok, "database or recognizer set-up failed");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t control = data[0];
  ++data;
  --size;
  uint32_t mode = (control >> 2) & 3u;
  if (mode >= kModeCount) mode = 0;
  const uint32_t thin_choice = (control >> 4) & 1u;
  fuzz::Session& s = fixture->sessions[thin_choice * kModeCount + mode];
  const double origin[3] = {0.0, 0.0, 0.0};
  Result r;
  uint32_t count = 0;
  switch (control & 3u) {
    case 0: {
      std::vector<float> p = raw_triples<float>(data, size);
      count = static_cast<uint32_t>(p.size() / 3);
      r = s.recognizer.recognize(p.data(), count);
      break;
    }
    case 3: {
      std::vector<double> p = raw_triples<double>(data, size);
      count = static_cast<uint32_t>(p.size() / 3);
      r = s.recognizer.recognize(p.data(), count);
      break;
    }
    default: {
      std::vector<double> p = centimetre_triples(data, size, (control & 3u) == 2u ? kUtmOffset : origin);
      count = static_cast<uint32_t>(p.size() / 3);
      r = s.recognizer.recognize(p.data(), count);
      break;
    }
  }
  fuzz::check_result(r, fixture->toy.db, count, s.workspace.size());
  return 0;
}
