#include "kernels/spin_entry.hpp"

namespace spinhash {
namespace kernels {

void spin_accumulate_reference(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                               float* image) {
  reference::spin_accumulate(b, g, p, n, image);
}
#if defined(SPINHASH_KERNELS_HAVE_SSE2_SPIN)
void spin_accumulate_sse2(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                          float* image) {
  sse2::spin_accumulate(b, g, p, n, image);
}
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_SPIN)
void spin_accumulate_neon(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                          float* image) {
  neon::spin_accumulate(b, g, p, n, image);
}
#endif
void spin_accumulate_selected(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                              float* image) {
  spin_accumulate(b, g, p, n, image);
}

}  // namespace kernels
}  // namespace spinhash
