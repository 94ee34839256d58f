// The neighbour-moments kernels of the normals
// (firmware-lib/kernels/*/moments.hpp), as tests/core/test_kernels.cpp does
// the L1 ones: every kernel built for this target against the scalar
// reference, bit for bit (memcmp), on random neighbourhoods of every count
// 0..1024 at unaligned addresses and on edge cases (empty, one point, points
// exactly on the radius, the centre itself, subnormal offsets, NaN).
// tests/core/test_exact_cuts.cpp checks the normals of the gathered
// neighbourhoods against the grid walk's.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "kernels/moments_entry.hpp"
#include "util/rng.hpp"

namespace spinhash {
namespace {

namespace k = kernels;

struct MomentsKernel {
  const char* name;
  k::MomentsAccumulate accumulate;
};

std::vector<MomentsKernel> built_moments_kernels() {
  std::vector<MomentsKernel> v;
#if defined(SPINHASH_KERNELS_HAVE_SSE2_MOMENTS)
  v.push_back({"sse2", k::moments_accumulate_sse2});
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_MOMENTS)
  v.push_back({"neon", k::moments_accumulate_neon});
#endif
  v.push_back({"selected", k::moments_accumulate_selected});
  return v;
}

constexpr uint32_t kMaxCount = 1024;
constexpr uint32_t kMisalign = 3;  // floats: the arrays start 0..3 floats past an aligned address
static_assert(sizeof(k::NeighbourMoments) == 10 * sizeof(float), "no padding: memcmp compares every bit");

float uniform(Pcg32* rng, float lo, float hi) {
  return lo + (hi - lo) * static_cast<float>(rng->next() >> 8) * (1.0f / 16777216.0f);
}

// A neighbourhood in three separate arrays, each starting `shift` floats into its buffer.
struct Neighbourhood {
  std::vector<float> buf[3];
  uint32_t shift = 0;
  explicit Neighbourhood(uint32_t capacity) {
    for (auto& b : buf) b.assign(capacity + kMisalign + 1u, 0.0f);
  }
  float* a(int i) { return buf[i].data() + shift; }
  k::MomentsNeighbours view(uint32_t count) { return k::MomentsNeighbours{a(0), a(1), a(2), count}; }
  void set(uint32_t i, const float* x) {
    for (int c = 0; c < 3; ++c) a(c)[i] = x[c];
  }
};

float squared_distance(const float* x, const float* q) {  // the kernels' expression
  const float ex = x[0] - q[0], ey = x[1] - q[1], ez = x[2] - q[2];
  return ex * ex + ey * ey + ez * ez;
}

// Sums to start from: a kernel adds to them, in order (never -0, as sums from +0 never are).
k::NeighbourMoments random_start(Pcg32* rng) {
  k::NeighbourMoments m;
  if (rng->next() % 4u == 0u) return m;
  for (float* f : {&m.s[0], &m.s[1], &m.s[2], &m.xy, &m.xz, &m.yz}) *f = uniform(rng, -3.0f, 3.0f);
  for (float* f : {&m.xx, &m.yy, &m.zz}) *f = uniform(rng, 0.0f, 3.0f);
  m.count = rng->next() % 1000u;
  return m;
}

bool same_bits(const k::NeighbourMoments& a, const k::NeighbourMoments& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// One random neighbour of q: inside or beyond the radius, the centre
// itself, on a cell-like grid of coordinates (repeated values), or a copy
// of the point that defines the radius (exactly on it).
void random_neighbour(Pcg32* rng, const float* q, float radius, const float* on_radius, float* x) {
  const uint32_t kind = rng->next() % 8u;
  for (int c = 0; c < 3; ++c) x[c] = q[c] + uniform(rng, -1.5f, 1.5f) * radius;
  if (kind == 0) {
    for (int c = 0; c < 3; ++c) x[c] = q[c];
  } else if (kind == 1) {
    for (int c = 0; c < 3; ++c) x[c] = on_radius[c];
  } else if (kind == 2) {
    for (int c = 0; c < 3; ++c) x[c] = 0.125f * std::round(8.0f * x[c]);
  }
}

TEST_CASE("moments kernels: every built kernel equals the reference bit for bit, counts 0-1024, unaligned") {
  Pcg32 rng(2930);
  Neighbourhood h(kMaxCount);
  uint32_t mismatches = 0, runs = 0;
  for (uint32_t count = 0; count <= kMaxCount; ++count) {
    const uint32_t shift = count % (kMisalign + 1u);
    h.shift = shift;
    const float q[3] = {uniform(&rng, -20.0f, 20.0f), uniform(&rng, -20.0f, 20.0f),
                        uniform(&rng, -5.0f, 5.0f)};
    const float radius = uniform(&rng, 0.1f, 1.0f);
    // The radius is that of a point's own squared distance: copies of it lie exactly on it.
    float on_radius[3] = {q[0] + radius * 0.6f, q[1] - radius * 0.8f, q[2]};
    const float r2 = count % 3u == 0u ? radius * radius : squared_distance(on_radius, q);
    for (uint32_t i = 0; i < count; ++i) {
      float x[3];
      random_neighbour(&rng, q, radius, on_radius, x);
      h.set(i, x);
    }
    const k::NeighbourMoments start = random_start(&rng);
    k::NeighbourMoments want = start;
    k::moments_accumulate_reference(h.view(count), q, r2, &want);
    for (const MomentsKernel& kern : built_moments_kernels()) {
      k::NeighbourMoments got = start;
      kern.accumulate(h.view(count), q, r2, &got);
      ++runs;
      if (!same_bits(got, want)) {
        CAPTURE(kern.name);
        CAPTURE(count);
        CAPTURE(shift);
        CHECK(same_bits(got, want));
        ++mismatches;
      }
    }
  }
  MESSAGE("moments kernels compared: " << runs);
  CHECK(mismatches == 0u);
}

// The reference's sums over pts from `start`, and every kernel's the same, at every shift.
void check_all(const std::vector<float>& pts, const float* q, float r2, uint32_t want_count) {
  const uint32_t count = static_cast<uint32_t>(pts.size() / 3u);
  for (uint32_t shift = 0; shift <= kMisalign; ++shift) {
    Neighbourhood h(count);
    h.shift = shift;
    for (uint32_t i = 0; i < count; ++i) h.set(i, pts.data() + 3u * i);
    k::NeighbourMoments want;
    k::moments_accumulate_reference(h.view(count), q, r2, &want);
    CHECK(want.count == want_count);
    for (const MomentsKernel& kern : built_moments_kernels()) {
      CAPTURE(kern.name);
      CAPTURE(count);
      CAPTURE(shift);
      k::NeighbourMoments got;
      kern.accumulate(h.view(count), q, r2, &got);
      CHECK(same_bits(got, want));
    }
  }
}

TEST_CASE("moments kernels: edge cases sum as the reference does") {
  const float q[3] = {0.5f, -0.25f, 1.0f};
  const float r2 = 0.25f;  // radius 0.5: offsets of 0.5 along an axis are exact
  SUBCASE("empty: the sums are untouched") { check_all({}, q, r2, 0u); }
  SUBCASE("one point: inside, beyond, on the radius, the centre itself") {
    check_all({0.6f, -0.2f, 1.1f}, q, r2, 1u);
    check_all({1.2f, -0.25f, 1.0f}, q, r2, 0u);
    check_all({1.0f, -0.25f, 1.0f}, q, r2, 1u);  // d2 == r2 exactly
    check_all({0.5f, -0.25f, 1.0f}, q, r2, 1u);
  }
  SUBCASE("points exactly on the radius, along every axis and both ways, in every lane") {
    std::vector<float> pts;
    for (int a = 0; a < 3; ++a)
      for (float sign : {1.0f, -1.0f}) {
        float x[3] = {q[0], q[1], q[2]};
        x[a] += sign * 0.5f;
        pts.insert(pts.end(), x, x + 3);
      }
    for (uint32_t n = 1; n <= 6; ++n)
      check_all(std::vector<float>(pts.begin(), pts.begin() + 3 * n), q, r2, n);
    // Just beyond: the next float out along x.
    check_all({std::nextafter(1.0f, 2.0f), -0.25f, 1.0f, 1.0f, -0.25f, 1.0f}, q, r2, 1u);
  }
  SUBCASE("subnormal offsets and products at the origin") {
    const float o[3] = {0.0f, 0.0f, 0.0f};
    const float tiny = std::numeric_limits<float>::denorm_min();
    check_all({1e-22f, -3e-23f, 0.0f, tiny, tiny, -tiny, -1e-20f, 2e-21f, 5e-22f, 0.0f, 0.0f, 0.0f, 1e-30f,
               1e-30f, 1e-30f},
              o, 1e-40f, 4u);  // the third, at 1.04e-40, is beyond
  }
  SUBCASE("NaN coordinates fail the test as the reference's does") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    check_all({nan, 0.0f, 1.0f, 0.6f, -0.2f, 1.1f, 0.5f, nan, 1.0f, 0.4f, -0.3f, 0.9f, 0.5f, -0.25f, nan}, q,
              r2, 2u);
  }
}

}  // namespace
}  // namespace spinhash
