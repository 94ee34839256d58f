#include "experiment/ground_filter.hpp"

#include <algorithm>

namespace spinhash::experiment {

size_t remove_level_ground(std::vector<double>* xyz) {
  const size_t n = xyz->size() / 3;
  if (n == 0) return 0;
  std::vector<double> z(n);
  for (size_t i = 0; i < n; ++i) z[i] = (*xyz)[3 * i + 2];
  const size_t k = static_cast<size_t>(kGroundPercentile * static_cast<double>(n - 1));
  std::nth_element(z.begin(), z.begin() + static_cast<std::ptrdiff_t>(k), z.end());
  const double floor = z[k] + kGroundClearance;
  size_t kept = 0;
  for (size_t i = 0; i < n; ++i) {
    if ((*xyz)[3 * i + 2] <= floor) continue;
    for (size_t a = 0; a < 3; ++a) (*xyz)[3 * kept + a] = (*xyz)[3 * i + a];
    ++kept;
  }
  xyz->resize(3 * kept);
  return n - kept;
}

}  // namespace spinhash::experiment
