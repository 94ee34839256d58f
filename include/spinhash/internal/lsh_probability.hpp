// Internal interface (tests and experiments; not installed, not in the core
// library): eq. 2, the probability that two spin images at L1 distance d
// share a bucket in at least one of L tables of K bits.
#pragma once
#include <cmath>
#include <cstdint>

namespace spinhash {

inline double lsh_collision_probability(double d, double d_c, uint32_t k, uint32_t l) {
  if (!(d_c > 0.0)) return 0.0;
  double p_bit = 1.0 - d / d_c;
  if (p_bit <= 0.0) return 0.0;
  if (p_bit > 1.0) p_bit = 1.0;
  return 1.0 - std::pow(1.0 - std::pow(p_bit, static_cast<double>(k)), static_cast<double>(l));
}

}  // namespace spinhash
