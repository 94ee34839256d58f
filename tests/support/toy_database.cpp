#include "support/toy_database.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "blob/blob_writer.hpp"
#include "support/geometry_fixtures.hpp"

namespace spinhash {
namespace test {
namespace {

struct Box {
  float cx, cy, cz, sx, sy, sz;
};

// Each toy is a hull plus a cabin or turret box; sizes differ by 0.3-1 m.
const Box kToyParts[kToyModels][2] = {
    {{0, 0, 0.75f, 4.5f, 1.8f, 0.9f}, {-0.3f, 0, 1.45f, 2.2f, 1.6f, 0.6f}},  // sedan-like
    {{0, 0, 0.9f, 5.0f, 2.0f, 1.2f}, {1.2f, 0, 1.8f, 1.6f, 1.9f, 0.8f}},     // pickup-like
    {{0, 0, 1.0f, 6.5f, 2.4f, 1.4f}, {-2.0f, 0, 2.1f, 1.8f, 2.3f, 1.0f}},    // truck-like
    {{0, 0, 0.8f, 6.0f, 3.0f, 1.0f}, {0.4f, 0, 1.6f, 2.4f, 2.0f, 0.7f}},     // tank-like
    {{0, 0, 1.1f, 4.8f, 2.0f, 1.6f}, {2.0f, 0, 0.7f, 0.8f, 1.9f, 0.8f}},     // van-like
    {{0, 0, 0.7f, 3.8f, 1.7f, 0.8f}, {0.2f, 0, 1.3f, 1.5f, 1.5f, 0.5f}},     // small car
};

const VehicleClass kToyClasses[kToyModels] = {VehicleClass::kSedan, VehicleClass::kPickup,
                                              VehicleClass::kTruck, VehicleClass::kTracked,
                                              VehicleClass::kVan,   VehicleClass::kSedan};

}  // namespace

VehicleClass toy_class(uint32_t index) {
  return index < kToyModels ? kToyClasses[index] : VehicleClass::kUnclassified;
}

std::vector<double> toy_vehicle_points(uint32_t index, float spacing) {
  std::vector<double> out;
  for (const Box& b : kToyParts[index]) {
    std::vector<float> s = box_surface(b.sx, b.sy, b.sz, spacing);
    for (size_t i = 0; i < s.size(); i += 3) {
      out.push_back(s[i] + b.cx);
      out.push_back(s[i + 1] + b.cy);
      out.push_back(s[i + 2] + b.cz);
    }
  }
  return out;
}

std::vector<host::ModelCloud> toy_clouds() {
  std::vector<host::ModelCloud> clouds;
  for (uint32_t i = 0; i < kToyModels; ++i)
    clouds.push_back(
        host::ModelCloud{"toy-" + std::to_string(i), toy_vehicle_points(i, 0.05f), toy_class(i)});
  return clouds;
}

bool make_database(const std::vector<host::ModelCloud>& clouds, ToyDatabase* out,
                   const host::BuildOptions& options) {
  host::BlobContent content;
  host::BuildReport report;
  std::string error;
  if (!host::build_database(clouds, options, &content, &report, &error)) return false;
  std::vector<uint8_t> bytes;
  if (!host::serialize_blob(content, host::ByteOrder::kNative, &bytes, &error)) return false;
  out->bytes = host::AlignedBytes::copy_of(bytes);
  return Database::open(out->bytes.data(), out->bytes.size(), &out->db) == Status::kOk;
}

bool make_toy_database(ToyDatabase* out, uint32_t twin_of) {
  std::vector<host::ModelCloud> clouds = toy_clouds();
  if (twin_of < kToyModels)
    clouds.push_back(host::ModelCloud{"toy-twin", toy_vehicle_points(twin_of, 0.05f), toy_class(twin_of)});
  return make_database(clouds, out);
}

const ToyDatabase& shared_toy_database(uint32_t twin_of) {
  static ToyDatabase toys[kToyModels + 1];  // the last: no twin; empty bytes: not built yet
  const uint32_t slot = twin_of < kToyModels ? twin_of : kToyModels;
  if (toys[slot].bytes.size() == 0 && !make_toy_database(&toys[slot], twin_of)) {
    std::fprintf(stderr, "the toy database (twin of %u) could not be built\n",
                 static_cast<unsigned>(twin_of));
    std::abort();
  }
  return toys[slot];
}

namespace {

constexpr double kHiddenFaceDepth = 0.02;  // m: the back and right faces (and their edges) are not seen
constexpr double kHiddenBottom = 0.2;      // m: nor those this low

// The points `seen` keeps, moved and noisy.
template <typename Seen>
std::vector<double> view(const std::vector<double>& model, double yaw, const double t[3], double noise,
                         uint64_t seed, Seen seen) {
  std::vector<double> out;
  const double c = std::cos(yaw), s = std::sin(yaw);
  uint64_t state = seed * 6364136223846793005ull + 1442695040888963407ull;
  auto uniform = [&state]() {  // deterministic, standard-library independent
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0);
  };
  for (size_t i = 0; i < model.size(); i += 3) {
    double x = model[i], y = model[i + 1], z = model[i + 2];
    if (!seen(x, y, z)) continue;
    double n = noise * (uniform() + uniform() + uniform() - 1.5) * 2.0;  // roughly Gaussian, sd ~ noise
    out.push_back(c * x - s * y + t[0] + n * 0.3);
    out.push_back(s * x + c * y + t[1] + n * 0.3);
    out.push_back(z + t[2] + n);
  }
  return out;
}

}  // namespace

std::vector<double> toy_query(const std::vector<double>& model, double yaw, const double t[3], double noise,
                              uint64_t seed) {
  // Seen from the front-left, above: about 2 sides + top.
  return view(model, yaw, t, noise, seed,
              [](double x, double y, double z) { return x >= -2.5 && y >= -0.5 && z >= 0.2; });
}

std::vector<double> toy_airborne_query(const std::vector<double>& model, double yaw, const double t[3],
                                       double noise, uint64_t seed) {
  double back = 1e9, right = 1e9;  // the vehicle's back and right faces
  for (size_t i = 0; i < model.size(); i += 3) {
    back = model[i] < back ? model[i] : back;
    right = model[i + 1] < right ? model[i + 1] : right;
  }
  return view(model, yaw, t, noise, seed, [&](double x, double y, double z) {
    return x >= back + kHiddenFaceDepth && y >= right + kHiddenFaceDepth && z >= kHiddenBottom;
  });
}

}  // namespace test
}  // namespace spinhash
