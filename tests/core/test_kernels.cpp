// The L1 kernels (firmware-lib/kernels/) in the manner of Eigen's packetmath
// test: every kernel built for this target against the scalar reference, at
// every length 1..1024, at unaligned addresses, on bytes of 0 and 255 and on
// random bytes, and l1_distance_within's contract, which the candidate
// search depends on.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "kernels/l1_select.hpp"
#include "spinhash/internal/l1_distance.hpp"
#include "util/rng.hpp"

namespace spinhash {
namespace {

namespace ref = kernels::reference;

struct L1Kernel {
  const char* name;
  uint32_t (*distance)(const uint8_t*, const uint8_t*, uint32_t);
  uint32_t (*within)(const uint8_t*, const uint8_t*, uint32_t, uint32_t);
};

// Every kernel this build holds (the optimised ones the target's flags
// allow, AVX2 when the CPU has it), the compile-time choice and the
// exported entry points host code calls.
std::vector<L1Kernel> built_kernels() {
  std::vector<L1Kernel> k;
#if defined(SPINHASH_KERNELS_HAVE_SSE2)
  k.push_back({kernels::sse2::kName, kernels::sse2::l1_distance, kernels::sse2::l1_distance_within});
#endif
#if defined(SPINHASH_KERNELS_HAVE_AVX2)
  if (__builtin_cpu_supports("avx2"))
    k.push_back({kernels::avx2::kName, kernels::avx2::l1_distance, kernels::avx2::l1_distance_within});
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON)
  k.push_back({kernels::neon::kName, kernels::neon::l1_distance, kernels::neon::l1_distance_within});
#endif
  k.push_back({"selected", kernels::l1_distance, kernels::l1_distance_within});
  k.push_back({"exported", l1_distance, l1_distance_within});
  return k;
}

constexpr uint32_t kMaxDims = 1024;
constexpr uint32_t kGuard = 64;  // bytes either side of an image
// Misalignments (from a 64-byte boundary) of the two images.
constexpr uint32_t kOffsets[][2] = {{0, 0}, {1, 3}, {7, 15}, {15, 1}, {33, 62}};

// Two images in 64-byte-aligned buffers, between guard bytes that differ
// (0 beside a, 255 beside b): a kernel that reads outside an image adds
// up to 255 per byte it should not have read.
struct ImagePair {
  alignas(64) uint8_t a[kGuard + kMaxDims + kGuard];
  alignas(64) uint8_t b[kGuard + kMaxDims + kGuard];
  uint8_t* pa = nullptr;
  uint8_t* pb = nullptr;
  void place(uint32_t offset_a, uint32_t offset_b) {
    std::memset(a, 0, sizeof a);
    std::memset(b, 255, sizeof b);
    pa = a + offset_a;
    pb = b + offset_b;
  }
};

enum class Fill { kRandom, kZeroVs255, k255VsZero, kEqual, kExtremes };
constexpr Fill kFills[] = {Fill::kRandom, Fill::kZeroVs255, Fill::k255VsZero, Fill::kEqual, Fill::kExtremes};

void fill(ImagePair* p, uint32_t dims, Fill f, Pcg32* rng) {
  for (uint32_t i = 0; i < dims; ++i) {
    const uint8_t r = static_cast<uint8_t>(rng->next()), s = static_cast<uint8_t>(rng->next());
    switch (f) {
      case Fill::kRandom: p->pa[i] = r, p->pb[i] = s; break;
      case Fill::kZeroVs255: p->pa[i] = 0, p->pb[i] = 255; break;
      case Fill::k255VsZero: p->pa[i] = 255, p->pb[i] = 0; break;
      case Fill::kEqual: p->pa[i] = r, p->pb[i] = r; break;
      case Fill::kExtremes: p->pa[i] = r & 1u ? 255 : 0, p->pb[i] = s & 1u ? 255 : 0; break;
    }
  }
}

// The bounds worth trying: around the exact distance, around the first
// block's partial sum (where the early exit decides), and the extremes.
std::vector<uint32_t> bounds_around(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t exact) {
  std::vector<uint32_t> v{0u, exact / 2u, exact, exact + 1u, 0xFFFFFFFFu};
  if (exact > 0) v.push_back(exact - 1u);
  if (dims >= kernels::kL1Block) {
    const uint32_t first = kernels::first_block(dims);
    const uint32_t head = ref::sad(a + first, b + first, kernels::kL1Block);
    v.push_back(head);
    if (head > 0) v.push_back(head - 1u);
  }
  return v;
}

// The contract the candidate search relies on, for one bound.
void check_within_contract(uint32_t within, uint32_t exact, uint32_t bound) {
  if (exact <= bound)
    CHECK(within == exact);
  else
    CHECK(within > bound);
}

TEST_CASE("kernels: the selected L1 kernel is the one the target's flags call for") {
  MESSAGE("selected L1 kernel: " << std::string(l1_kernel_name()));
  const char* expected = "reference";
#if defined(SPINHASH_KERNELS_REFERENCE)
  expected = "reference";
#elif defined(__AVX2__)
  expected = "avx2";
#elif defined(__x86_64__)
  expected = "sse2";
#elif defined(__ARM_NEON)  // aarch64, and armhf built with -mfpu=neon
  expected = "neon";
#endif
  CHECK(std::strcmp(l1_kernel_name(), expected) == 0);
  CHECK(std::strcmp(kernels::selected::kName, expected) == 0);
}

TEST_CASE(
    "kernels: every built L1 kernel equals the reference for dims 1-1024, unaligned, 0/255/random bytes") {
  static ImagePair p;
  Pcg32 rng(29);
  for (const L1Kernel& k : built_kernels()) {
    CAPTURE(k.name);
    for (const auto& off : kOffsets) {
      p.place(kGuard + off[0], kGuard + off[1]);
      for (Fill f : kFills) {
        for (uint32_t dims = 1; dims <= kMaxDims; ++dims) {
          fill(&p, dims, f, &rng);
          const uint32_t exact = ref::l1_distance(p.pa, p.pb, dims);
          const uint32_t got = k.distance(p.pa, p.pb, dims);
          if (got != exact) {  // one report per failure, not a million passing checks
            CAPTURE(dims);
            CAPTURE(off[0]);
            CAPTURE(static_cast<int>(f));
            CHECK(got == exact);
          }
        }
      }
    }
  }
}

TEST_CASE("kernels: every built l1_distance_within equals the reference and keeps its contract") {
  static ImagePair p;
  Pcg32 rng(31);
  uint32_t failures = 0;
  for (const L1Kernel& k : built_kernels()) {
    CAPTURE(k.name);
    for (const auto& off : kOffsets) {
      p.place(kGuard + off[0], kGuard + off[1]);
      for (Fill f : {Fill::kRandom, Fill::kZeroVs255, Fill::kEqual}) {
        for (uint32_t dims = 1; dims <= kMaxDims; ++dims) {
          fill(&p, dims, f, &rng);
          const uint32_t exact = ref::l1_distance(p.pa, p.pb, dims);
          for (uint32_t bound : bounds_around(p.pa, p.pb, dims, exact)) {
            const uint32_t expected = ref::l1_distance_within(p.pa, p.pb, dims, bound);
            const uint32_t got = k.within(p.pa, p.pb, dims, bound);
            const bool kept = exact <= bound ? got == exact : got > bound;
            if (got == expected && kept) continue;
            CAPTURE(dims);
            CAPTURE(bound);
            CHECK(got == expected);
            check_within_contract(got, exact, bound);
            ++failures;
          }
        }
      }
    }
  }
  CHECK(failures == 0u);
}

TEST_CASE("kernels: the reference's l1_distance_within keeps its contract and stops at the first block") {
  static ImagePair p;
  p.place(kGuard, kGuard);
  Pcg32 rng(37);
  for (uint32_t dims : {1u, 17u, 63u, 64u, 65u, 100u, 129u, 225u, 1024u}) {
    fill(&p, dims, Fill::kRandom, &rng);
    const uint32_t exact = ref::l1_distance(p.pa, p.pb, dims);
    for (uint32_t bound : bounds_around(p.pa, p.pb, dims, exact))
      check_within_contract(ref::l1_distance_within(p.pa, p.pb, dims, bound), exact, bound);
  }
  // Far images: the scan stops after the first 64-byte block, whose sum it returns.
  fill(&p, 100, Fill::kZeroVs255, &rng);
  CHECK(ref::l1_distance_within(p.pa, p.pb, 100, 10u) == 64u * 255u);
  CHECK(ref::l1_distance_within(p.pa, p.pb, 100, 64u * 255u) == 100u * 255u);
}

TEST_CASE("kernels: every built L1 kernel is exact on all 65 536 byte pairs") {
  alignas(64) uint8_t a[256], b[256];
  for (const L1Kernel& k : built_kernels()) {
    CAPTURE(k.name);
    uint32_t mismatches = 0;
    for (uint32_t shift = 0; shift < 256; ++shift) {
      for (uint32_t i = 0; i < 256; ++i)
        a[i] = static_cast<uint8_t>(i), b[i] = static_cast<uint8_t>(i + shift);
      for (uint32_t n : {1u, 8u, 15u, 100u, 256u})
        mismatches += k.distance(a, b, n) != ref::l1_distance(a, b, n) ? 1u : 0u;
    }
    CHECK(mismatches == 0u);
  }
}

TEST_CASE("kernels: long images of 0 against 255 do not overflow a kernel's partial sums") {
  constexpr uint32_t kLong = 16384;  // past NEON's 16-bit lanes (flushed every 1 KiB)
  std::vector<uint8_t> zeros(kLong, 0), full(kLong, 255);
  for (const L1Kernel& k : built_kernels()) {
    CAPTURE(k.name);
    for (uint32_t n : {1024u, 1040u, 2048u, 4095u, kLong}) {
      CAPTURE(n);
      CHECK(k.distance(zeros.data(), full.data(), n) == n * 255u);
      CHECK(k.distance(full.data(), zeros.data(), n) == n * 255u);
      CHECK(k.within(full.data(), zeros.data(), n, 0xFFFFFFFFu) == n * 255u);
    }
  }
}

}  // namespace
}  // namespace spinhash
