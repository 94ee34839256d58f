#include "support/toy_copies.hpp"

#include <string>
#include <vector>

namespace spinhash {
namespace test {

constexpr float kSpacing = 0.05f;  // m, the copies' and the view's surface points

bool make_toy_copies(uint32_t copies, double shift, ToyDatabase* out) {
  std::vector<host::ModelCloud> clouds;
  for (uint32_t i = 0; i < copies; ++i) {
    std::vector<double> points = toy_vehicle_points(kCopiedToy, kSpacing);
    for (size_t p = 0; p < points.size(); p += 3) points[p] += shift * i;
    clouds.push_back(host::ModelCloud{"copy-" + std::to_string(i), points});
  }
  return make_database(clouds, out);
}

Result recognize_copied_toy(const ToyDatabase& toy, const RecognizerConfig& cfg, host::AlignedBytes* ws) {
  *ws = host::AlignedBytes(required_workspace_bytes(cfg));
  Recognizer r;
  if (r.init(&toy.db, cfg, ws->data(), ws->size()) != Status::kOk) return Result{};
  const double t[3] = {-30.0, 55.0, 2.0};
  std::vector<double> q = toy_query(toy_vehicle_points(kCopiedToy, kSpacing), -0.4, t, 0.03, 9);
  return r.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
}

}  // namespace test
}  // namespace spinhash
