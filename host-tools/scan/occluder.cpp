#include "scan/occluder.hpp"

#include <algorithm>
#include <cmath>

namespace spinhash::host {

void apply_slab_occluder(const std::vector<double>& xyz, const std::vector<uint8_t>& on_object,
                         double fraction, SeededRandom* rng, std::vector<uint8_t>* keep) {
  constexpr double kTwoPi = 6.283185307179586;
  const std::size_t n = on_object.size();
  keep->assign(n, 1);
  const double angle = rng->uniform(0.0, kTwoPi);
  const double hx = std::cos(angle);
  const double hy = std::sin(angle);
  // Offsets of object points across the slab; the slab is chosen as a run
  // of consecutive offsets, so it holds the wanted number of points exactly
  // (up to ties).
  std::vector<double> across(n);
  std::vector<double> sorted;
  for (std::size_t i = 0; i < n; ++i) {
    across[i] = hx * xyz[3 * i] + hy * xyz[3 * i + 1];
    if (on_object[i]) sorted.push_back(across[i]);
  }
  const auto hidden = static_cast<std::size_t>(std::llround(fraction * sorted.size()));
  if (hidden == 0 || hidden > sorted.size()) return;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t first = rng->below(static_cast<uint32_t>(sorted.size() - hidden + 1));
  const double lo = sorted[first];
  const double hi = sorted[first + hidden - 1];
  for (std::size_t i = 0; i < n; ++i) {
    if (on_object[i] && across[i] >= lo && across[i] <= hi) (*keep)[i] = 0;
  }
}

}  // namespace spinhash::host
