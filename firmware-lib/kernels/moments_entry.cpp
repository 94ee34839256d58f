#include "kernels/moments_entry.hpp"

namespace spinhash {
namespace kernels {

void moments_accumulate_reference(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  reference::moments_accumulate(g, q, r2, m);
}
#if defined(SPINHASH_KERNELS_HAVE_SSE2_MOMENTS)
void moments_accumulate_sse2(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  sse2::moments_accumulate(g, q, r2, m);
}
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_MOMENTS)
void moments_accumulate_neon(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  neon::moments_accumulate(g, q, r2, m);
}
#endif
void moments_accumulate_selected(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  moments_accumulate(g, q, r2, m);
}

}  // namespace kernels
}  // namespace spinhash
