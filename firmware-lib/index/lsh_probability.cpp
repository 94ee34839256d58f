#include <cmath>

#include "spinhash/lsh.hpp"

namespace spinhash {

double lsh_collision_probability(double d, double d_c, uint32_t k, uint32_t l) {
  if (!(d_c > 0.0)) return 0.0;
  double p_bit = 1.0 - d / d_c;
  if (p_bit <= 0.0) return 0.0;
  if (p_bit > 1.0) p_bit = 1.0;
  return 1.0 - std::pow(1.0 - std::pow(p_bit, static_cast<double>(k)), static_cast<double>(l));
}

}  // namespace spinhash
