// The spin-image accumulation kernels (firmware-lib/kernels/*/spin.hpp), as
// tests/core/test_kernels.cpp does the L1 ones: every kernel built for this
// target against the scalar reference, bit for bit (memcmp), on random
// neighbourhoods of every count 0..kMaxCount at unaligned addresses and on
// edge cases (points exactly on the radius and on the support angle, zero
// alpha, no normals, the support test off, rim bins); then the cell-by-cell
// images of compute_spin_images against compute_spin_image's grid walk
// (which reference builds, SPINHASH_KERNELS_REFERENCE, use for both).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "descriptor/spin_images.hpp"
#include "kernels/spin_entry.hpp"
#include "support/grid_fixture.hpp"
#include "util/rng.hpp"

namespace spinhash {
namespace {

namespace k = kernels;

struct SpinKernel {
  const char* name;
  k::SpinAccumulate accumulate;
};

std::vector<SpinKernel> built_spin_kernels() {
  std::vector<SpinKernel> v;
#if defined(SPINHASH_KERNELS_HAVE_SSE2_SPIN)
  v.push_back({"sse2", k::spin_accumulate_sse2});
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_SPIN)
  v.push_back({"neon", k::spin_accumulate_neon});
#endif
  v.push_back({"selected", k::spin_accumulate_selected});
  return v;
}

constexpr uint32_t kMaxCount = 67;  // past several 4-lane blocks and every tail length
constexpr uint32_t kMisalign = 3;   // floats: the arrays start at 0..3 floats past an aligned address
constexpr float kNoNormal = std::numeric_limits<float>::quiet_NaN();

float uniform(Pcg32* rng, float lo, float hi) {
  return lo + (hi - lo) * static_cast<float>(rng->next() >> 8) * (1.0f / 16777216.0f);
}

// A neighbourhood in six separate arrays, each starting `shift` floats into its buffer.
struct Neighbourhood {
  std::vector<float> buf[6];
  uint32_t shift = 0;
  explicit Neighbourhood(uint32_t capacity) {
    for (auto& b : buf) b.assign(capacity + kMisalign + 1u, 0.0f);
  }
  float* a(int i) { return buf[i].data() + shift; }
  k::SpinNeighbours view(uint32_t count) {
    return k::SpinNeighbours{a(0), a(1), a(2), a(3), a(4), a(5), count};
  }
  void set(uint32_t i, const float* x, const float* nrm) {
    for (int c = 0; c < 3; ++c) a(c)[i] = x[c], a(3 + c)[i] = nrm[c];
  }
};

k::SpinGeometry geometry(float radius, uint32_t ba, uint32_t bb, bool support, float cos_support) {
  SpinImageParams sp;
  sp.radius = radius;
  sp.bins_alpha = ba;
  sp.bins_beta = bb;
  sp.use_support_angle = support;
  sp.cos_support_angle = cos_support;
  return spin_geometry(sp);
}

void unit(float* v) {
  const float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int c = 0; c < 3; ++c) v[c] /= l;
}

// One random neighbour of (p, n): inside, on or beyond the radius; on the
// normal line (alpha 0) or off it; with a normal, none, or one exactly on
// the support angle.
void random_neighbour(Pcg32* rng, const k::SpinGeometry& b, const float* p, const float* n, float* x,
                      float* nrm) {
  const uint32_t kind = rng->next() % 8u;
  float d[3] = {uniform(rng, -1.3f, 1.3f), uniform(rng, -1.3f, 1.3f), uniform(rng, -1.3f, 1.3f)};
  if (kind == 0) {  // on the normal line: alpha 0 (or a rounding either side of it)
    const float t = uniform(rng, -1.0f, 1.0f);
    for (int c = 0; c < 3; ++c) d[c] = t * n[c];
  } else if (kind == 1) {  // exactly on an axis at the radius: d2 == r2
    for (int c = 0; c < 3; ++c) d[c] = 0.0f;
    d[rng->next() % 3u] = (rng->next() & 1u) ? 1.0f : -1.0f;
  } else {
    for (int c = 0; c < 3; ++c) d[c] *= b.radius;
  }
  for (int c = 0; c < 3; ++c) x[c] = p[c] + (kind == 1 ? d[c] * b.radius : d[c]);
  const uint32_t normal_kind = rng->next() % 6u;
  if (normal_kind == 0) {
    nrm[0] = nrm[1] = nrm[2] = kNoNormal;
  } else if (normal_kind == 1) {  // the basis normal itself: n . n = 1 (>= every cos)
    for (int c = 0; c < 3; ++c) nrm[c] = n[c];
  } else {
    for (int c = 0; c < 3; ++c) nrm[c] = uniform(rng, -1.0f, 1.0f);
    unit(nrm);
  }
}

// Images start from random contents: a kernel adds to them, in order.
void random_image(Pcg32* rng, std::vector<float>* img) {
  for (float& v : *img) v = uniform(rng, 0.0f, 2.0f);
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

struct Case {
  float radius;
  uint32_t ba, bb;
  bool support;
  float cos_support;
};
constexpr Case kCases[] = {
    {1.0f, 10, 10, true, 0.5f},  {1.0f, 10, 10, false, 0.5f}, {1.0f, 10, 10, true, -0.3f},
    {1.0f, 10, 10, true, 1.0f},  {0.37f, 7, 13, true, 0.1f},  {2.5f, 1, 1, true, 0.5f},
    {0.6f, 32, 32, false, 0.0f}, {1.0f, 1, 32, true, 0.9f},
};

TEST_CASE("spin kernels: every built kernel equals the reference bit for bit, counts 0-67, unaligned") {
  Pcg32 rng(2029);
  Neighbourhood h(kMaxCount);
  uint32_t mismatches = 0, runs = 0;
  for (const Case& cs : kCases) {
    const k::SpinGeometry b = geometry(cs.radius, cs.ba, cs.bb, cs.support, cs.cos_support);
    std::vector<float> start(cs.ba * cs.bb), want(start.size()), got(start.size());
    for (uint32_t count = 0; count <= kMaxCount; ++count) {
      for (uint32_t shift = 0; shift <= kMisalign; ++shift) {
        h.shift = shift;
        const float p[3] = {uniform(&rng, -5.0f, 5.0f), uniform(&rng, -5.0f, 5.0f),
                            uniform(&rng, -5.0f, 5.0f)};
        float n[3] = {uniform(&rng, -1.0f, 1.0f), uniform(&rng, -1.0f, 1.0f), uniform(&rng, -1.0f, 1.0f)};
        if (count % 5u == 0u)
          n[0] = 0.0f, n[1] = 0.0f, n[2] = 1.0f;  // axis normal: exact alpha 0, exact dots
        unit(n);
        for (uint32_t i = 0; i < count; ++i) {
          float x[3], nrm[3];
          random_neighbour(&rng, b, p, n, x, nrm);
          h.set(i, x, nrm);
        }
        random_image(&rng, &start);
        want = start;
        k::spin_accumulate_reference(b, h.view(count), p, n, want.data());
        for (const SpinKernel& kern : built_spin_kernels()) {
          got = start;
          kern.accumulate(b, h.view(count), p, n, got.data());
          ++runs;
          if (!same_bits(got, want)) {
            CAPTURE(kern.name);
            CAPTURE(count);
            CAPTURE(shift);
            CAPTURE(cs.ba);
            CHECK(same_bits(got, want));
            ++mismatches;
          }
        }
      }
    }
  }
  MESSAGE("spin kernels compared: " << runs);
  CHECK(mismatches == 0u);
}

TEST_CASE("spin kernels: edge cases vote as the reference does") {
  // Normal +z at the origin, 1 m radius, 10 x 10 bins, support cos 0.5.
  const k::SpinGeometry b = geometry(1.0f, 10, 10, true, 0.5f);
  const float p[3] = {0.0f, 0.0f, 0.0f}, n[3] = {0.0f, 0.0f, 1.0f};
  const float up[3] = {0.0f, 0.0f, 1.0f}, on_angle[3] = {0.8660254f, 0.0f, 0.5f};
  const float away[3] = {0.0f, 0.0f, -1.0f}, none[3] = {kNoNormal, kNoNormal, kNoNormal};
  struct Point {
    float x[3];
    const float* nrm;
    bool votes;  // what the reference must do
  };
  const Point pts[] = {
      {{1.0f, 0.0f, 0.0f}, up, true},        // exactly on the radius (d2 == r2)
      {{0.0f, 0.0f, -1.0f}, up, true},       // on the radius along the normal: alpha 0, beta -R
      {{0.0f, 0.0f, 0.0f}, up, true},        // the point itself: alpha 0, beta 0
      {{0.0f, 0.0f, 0.5f}, on_angle, true},  // normal exactly at the support angle (n . n_x == cos)
      {{0.3f, 0.0f, 0.0f}, away, false},     // facing away
      {{0.3f, 0.2f, 0.0f}, none, false},     // no normal
      {{1.0f, 0.0f, 0.01f}, up, false},      // just beyond the radius
      {{0.0f, 0.99f, 0.0f}, up, true},       // the alpha rim
  };
  constexpr uint32_t kCount = sizeof pts / sizeof pts[0];
  for (uint32_t count = 1; count <= kCount; ++count) {
    for (uint32_t shift = 0; shift <= kMisalign; ++shift) {
      Neighbourhood h(kCount);
      h.shift = shift;
      for (uint32_t i = 0; i < count; ++i) h.set(i, pts[i].x, pts[i].nrm);
      std::vector<float> want(100, 0.0f);
      k::spin_accumulate_reference(b, h.view(count), p, n, want.data());
      float total = 0.0f;
      for (float v : want) total += v;
      uint32_t voters = 0;
      for (uint32_t i = 0; i < count; ++i) voters += pts[i].votes ? 1u : 0u;
      CHECK(total == doctest::Approx(static_cast<double>(voters)));  // a vote weighs 1 in all
      for (const SpinKernel& kern : built_spin_kernels()) {
        CAPTURE(kern.name);
        CAPTURE(count);
        std::vector<float> got(100, 0.0f);
        kern.accumulate(b, h.view(count), p, n, got.data());
        CHECK(same_bits(got, want));
      }
    }
  }
  // The support test off: the facing-away and normal-less points vote too.
  const k::SpinGeometry all = geometry(1.0f, 10, 10, false, 0.5f);
  Neighbourhood h(kCount);
  for (uint32_t i = 0; i < kCount; ++i) h.set(i, pts[i].x, pts[i].nrm);
  std::vector<float> want(100, 0.0f);
  k::spin_accumulate_reference(all, h.view(kCount), p, n, want.data());
  float total = 0.0f;
  for (float v : want) total += v;
  CHECK(total == doctest::Approx(7.0));  // all but the one beyond the radius
  for (const SpinKernel& kern : built_spin_kernels()) {
    CAPTURE(kern.name);
    std::vector<float> got(100, 0.0f);
    kern.accumulate(all, h.view(kCount), p, n, got.data());
    CHECK(same_bits(got, want));
  }
}

// A cloud of noisy planes and clutter, some normals missing; points on
// cell boundaries and exactly one support radius from a basis point.
struct Cloud {
  std::vector<float> pts, normals;
  std::vector<uint8_t> has;
  std::vector<uint32_t> basis;
};

Cloud random_cloud(Pcg32* rng, uint32_t n, float extent) {
  Cloud c;
  for (uint32_t i = 0; i < n; ++i) {
    float x[3] = {uniform(rng, 0.0f, extent), uniform(rng, 0.0f, extent), uniform(rng, 0.0f, 0.3f * extent)};
    if (i % 7u == 0u) x[0] = 0.5f * static_cast<float>(rng->next() % 8u);  // on a cell boundary
    if (i % 11u == 3u && i > 0) {                                          // one radius from point 0
      for (int a = 0; a < 3; ++a) x[a] = c.pts[a];
      x[0] += 1.0f;
    }
    float nrm[3] = {uniform(rng, -0.3f, 0.3f), uniform(rng, -0.3f, 0.3f), 1.0f};
    unit(nrm);
    for (int a = 0; a < 3; ++a) c.pts.push_back(x[a]), c.normals.push_back(nrm[a]);
    c.has.push_back(rng->next() % 9u == 0u ? 0u : 1u);
    if (i % 3u == 0u && c.has.back()) c.basis.push_back(i);
  }
  return c;
}

// compute_spin_images with scratch room for `capacity` gathered points.
std::vector<float> images_gathered(const SpinImageParams& sp, const test::GridFixture& g, const Cloud& c,
                                   uint32_t capacity) {
  const uint32_t n = static_cast<uint32_t>(c.has.size()), nb = static_cast<uint32_t>(c.basis.size());
  std::vector<float> arrays(6u * capacity + 1u);
  std::vector<uint32_t> basis_of(n);
  SpinScratch s;
  s.basis_of = basis_of.data();
  s.capacity = capacity;
  s.x = arrays.data();
  s.y = s.x + capacity;
  s.z = s.y + capacity;
  s.nx = s.z + capacity;
  s.ny = s.nx + capacity;
  s.nz = s.ny + capacity;
  std::vector<float> out(static_cast<size_t>(nb) * sp.bins_alpha * sp.bins_beta, -1.0f);
  compute_spin_images(sp, g.grid, c.pts.data(), n, c.normals.data(), c.has.data(), c.basis.data(), nb, s,
                      out.data());
  return out;
}

TEST_CASE("spin kernels: cell-by-cell gathered images equal the grid walk's bit for bit") {
  Pcg32 rng(4242);
  for (uint32_t trial = 0; trial < 6; ++trial) {
    CAPTURE(trial);
    const Cloud c = random_cloud(&rng, 400u + 300u * trial, 3.0f + static_cast<float>(trial));
    SpinImageParams sp;
    sp.radius = 1.0f;
    sp.use_support_angle = trial % 3u != 2u;
    sp.cos_support_angle = trial % 3u == 1u ? -0.2f : 0.5f;
    const test::GridFixture g(c.pts, 0.5f);  // the extractor's cell: R / 2, reach 2
    const uint32_t dims = sp.bins_alpha * sp.bins_beta, nb = static_cast<uint32_t>(c.basis.size());
    std::vector<float> walk(static_cast<size_t>(nb) * dims);
    for (uint32_t kb = 0; kb < nb; ++kb) {
      const uint32_t i = c.basis[kb];
      compute_spin_image(sp, g.grid, c.pts.data(), c.normals.data(), c.has.data(), c.pts.data() + 3u * i,
                         c.normals.data() + 3u * i, walk.data() + static_cast<size_t>(kb) * dims);
    }
    // Room for every neighbourhood, for some (the rest overflow to the walk), for none.
    for (uint32_t capacity : {static_cast<uint32_t>(c.has.size()), 150u, 1u, 0u}) {
      CAPTURE(capacity);
      CHECK(same_bits(images_gathered(sp, g, c, capacity), walk));
    }
  }
}

}  // namespace
}  // namespace spinhash
