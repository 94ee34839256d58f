// The selected L1 kernel behind include/spinhash/internal/l1_distance.hpp,
// for host code (the database builder, the experiments, the tests).
#include "spinhash/internal/l1_distance.hpp"

#include "kernels/l1_select.hpp"

namespace spinhash {

uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  return kernels::l1_distance(a, b, dims);
}

uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  return kernels::l1_distance_within(a, b, dims, bound);
}

const char* l1_kernel_name() { return kernels::selected::kName; }

}  // namespace spinhash
