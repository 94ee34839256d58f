// The nearest-feature kernels of verification
// (firmware-lib/kernels/*/nearest.hpp), as tests/core/test_kernels.cpp does
// the L1 ones: every kernel built for this target against the scalar
// reference, bit for bit (memcmp), on random poses and features (counts
// 1..1024 of them, read at unaligned addresses) and on edge cases (the
// identity, zero and subnormal coordinates, inf and NaN, coordinates
// exactly on the field's faces and one float inside or outside them). The
// frame change must also equal refinement's Eigen expression
// (query_in_model_frame), whose rounding differs by target (aarch64's
// Eigen fuses rows 0-1): the reference is that expression.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "kernels/nearest_entry.hpp"
#include "util/rng.hpp"

namespace spinhash {
namespace {

namespace k = kernels;

struct NearestKernel {
  const char* name;
  k::ToModelFrame frame;
  k::FieldVoxel voxel;
};

std::vector<NearestKernel> built_nearest_kernels() {
  std::vector<NearestKernel> v;
#if defined(SPINHASH_KERNELS_HAVE_SSE2_NEAREST)
  v.push_back({"sse2", k::to_model_frame_sse2, k::field_voxel_sse2});
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_NEAREST)
  v.push_back({"neon", k::to_model_frame_neon, k::field_voxel_neon});
#endif
  v.push_back({"selected", k::to_model_frame_selected, k::field_voxel_selected});
  return v;
}

constexpr uint32_t kMaxCount = 1024;
constexpr uint32_t kMisalign = 3;  // floats: features start 0..3 floats past an aligned address

// x, y, z equal bit for bit, but a NaN need only meet a NaN: which NaN
// operand's payload and sign an operation passes on follows the operand
// order, which a compiler may commute (the sanitizers' build does, for
// inf x 0 and NaN inputs). Every other result, -0 and subnormals included,
// is compared by its bits.
bool same_xyz(const float* a, const float* b) {
  for (int i = 0; i < 3; ++i)
    if (!(std::isnan(a[i]) && std::isnan(b[i])) && std::memcmp(a + i, b + i, sizeof(float)) != 0)
      return false;
  return true;
}

float uniform(Pcg32* rng, float lo, float hi) {
  return lo + (hi - lo) * static_cast<float>(rng->next() >> 8) * (1.0f / 16777216.0f);
}

// A random rotation (unit quaternion) and translation, as a pose's frame change.
k::FrameChange random_frame(Pcg32* rng) {
  float q[4], norm2 = 0.0f;
  for (float& c : q) c = uniform(rng, -1.0f, 1.0f), norm2 += c * c;
  const float s = 1.0f / std::sqrt(norm2 > 1e-6f ? norm2 : 1.0f);
  const float w = q[0] * s, x = q[1] * s, y = q[2] * s, z = q[3] * s;
  const float r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                         {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                         {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  k::FrameChange f;
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 3; ++i) f.col[c][i] = r[c][i];
    f.col[c][3] = 0.0f;
    f.t[c] = uniform(rng, -500.0f, 500.0f);
  }
  f.t[3] = 0.0f;
  return f;
}

// Every kernel's frame change of (q, qn) equals the reference's and Eigen's in lanes 0-2.
void check_frame(const k::FrameChange& f, const float* q, const float* qn, uint32_t* mismatches) {
  alignas(16) float want_x[4] = {}, want_n[4] = {}, eigen_x[4] = {}, eigen_n[4] = {};
  k::to_model_frame_reference(f, q, qn, want_x, want_n);
  k::to_model_frame_eigen(f, q, qn, eigen_x, eigen_n);
  if (!same_xyz(want_x, eigen_x) || !same_xyz(want_n, eigen_n)) {
    CHECK_MESSAGE(false, "the reference differs from query_in_model_frame");
    ++*mismatches;
  }
  for (const NearestKernel& kern : built_nearest_kernels()) {
    float got[10];  // x at got + 1, n at got + 5: unaligned outputs
    kern.frame(f, q, qn, got + 1, got + 5);
    if (!same_xyz(got + 1, want_x) || !same_xyz(got + 5, want_n)) {
      CAPTURE(kern.name);
      CHECK_MESSAGE(false, "frame change differs from the reference");
      ++*mismatches;
    }
  }
}

TEST_CASE("nearest kernels: the frame change equals the reference bit for bit, counts 1-1024, unaligned") {
  Pcg32 rng(2931);
  std::vector<float> pos(3u * kMaxCount + kMisalign), nrm(3u * kMaxCount + kMisalign);
  uint32_t mismatches = 0, runs = 0;
  for (uint32_t count = 1; count <= kMaxCount; count = count < 64u ? count + 1u : count * 2u) {
    const uint32_t shift = count % (kMisalign + 1u);
    const k::FrameChange f = random_frame(&rng);
    float* p = pos.data() + shift;
    float* n = nrm.data() + shift;
    for (uint32_t i = 0; i < 3u * count; ++i) {
      p[i] = f.t[i % 3u] + uniform(&rng, -4.0f, 4.0f);
      n[i] = uniform(&rng, -1.0f, 1.0f);
    }
    // The last feature ends the array: a kernel must not read past it (ASan, valgrind).
    std::vector<float> last(p + 3u * (count - 1u), p + 3u * count),
        last_n(n + 3u * (count - 1u), n + 3u * count);
    for (uint32_t l = 0; l < count; ++l, ++runs) check_frame(f, p + 3u * l, n + 3u * l, &mismatches);
    check_frame(f, last.data(), last_n.data(), &mismatches);
  }
  MESSAGE("frame changes compared: " << runs);
  CHECK(mismatches == 0u);
}

TEST_CASE("nearest kernels: frame change edge cases") {
  Pcg32 rng(2932);
  const float tiny = std::numeric_limits<float>::denorm_min();
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  k::FrameChange identity = {};
  for (int c = 0; c < 3; ++c) identity.col[c][c] = 1.0f;
  const k::FrameChange frames[] = {identity, random_frame(&rng), random_frame(&rng)};
  const float points[][3] = {{0.0f, 0.0f, 0.0f},     {-0.0f, 0.0f, -0.0f},  {tiny, -tiny, tiny},
                             {1e-38f, 3e-39f, 0.0f}, {inf, 0.0f, 1.0f},     {nan, 2.0f, -inf},
                             {1e30f, -1e30f, 1e30f}, {0.5f, 0.25f, -0.125f}};
  uint32_t mismatches = 0;
  for (const k::FrameChange& f : frames)
    for (const auto& q : points)
      for (const auto& qn : points) {
        float shifted_q[3] = {q[0] + f.t[0], q[1] + f.t[1], q[2] + f.t[2]};
        check_frame(f, q, qn, &mismatches);
        check_frame(f, shifted_q, qn, &mismatches);  // offsets of exactly q from the translation
      }
  CHECK(mismatches == 0u);
}

// A field box with a random corner, voxel edge and size.
k::FieldBox random_box(Pcg32* rng) {
  k::FieldBox b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = uniform(rng, -30.0f, 30.0f);
    b.dims[a] = static_cast<float>(1u + rng->next() % 40u);
  }
  b.lo[3] = 0.0f;
  b.dims[3] = 1.0f;
  b.cell = rng->next() % 2u == 0u ? 0.4f : uniform(rng, 0.05f, 1.0f);
  return b;
}

// Every kernel's voxel of x equals the reference's (the answer, and v[0..2] when inside).
bool check_voxel(const k::FieldBox& b, const float* x, uint32_t* mismatches) {
  uint32_t want[4] = {};
  const bool inside = k::field_voxel_reference(b, x, want);
  for (const NearestKernel& kern : built_nearest_kernels()) {
    uint32_t got[4] = {};
    const bool got_inside = kern.voxel(b, x, got);
    if (got_inside != inside || (inside && std::memcmp(got, want, 3 * sizeof(uint32_t)) != 0)) {
      CAPTURE(kern.name);
      CAPTURE(inside);
      CHECK_MESSAGE(false, "field voxel differs from the reference");
      ++*mismatches;
    }
  }
  return inside;
}

// A coordinate near the box on axis a: inside, beyond, on a face, one float either side of one.
float random_coordinate(Pcg32* rng, const k::FieldBox& b, int a) {
  const float hi = b.lo[a] + b.dims[a] * b.cell;
  const uint32_t kind = rng->next() % 8u;
  if (kind == 0) return b.lo[a];
  if (kind == 1) return hi;
  if (kind == 2) return std::nextafter(b.lo[a], -1e9f);
  if (kind == 3) return std::nextafter(hi, 1e9f);
  if (kind == 4) return std::nextafter(hi, -1e9f);
  if (kind == 5) return b.lo[a] + static_cast<float>(rng->next() % 41u) * b.cell;  // on a voxel face
  return uniform(rng, b.lo[a] - 2.0f, hi + 2.0f);
}

TEST_CASE("nearest kernels: the field voxel equals the reference, faces and one float either side") {
  Pcg32 rng(2933);
  uint32_t mismatches = 0, inside = 0, runs = 0;
  std::vector<float> xs(4u * kMaxCount + kMisalign);
  for (uint32_t count = 1; count <= kMaxCount; count = count < 64u ? count + 1u : count * 2u) {
    const k::FieldBox b = random_box(&rng);
    float* x = xs.data() + count % (kMisalign + 1u);  // four floats per point, unaligned
    for (uint32_t i = 0; i < count; ++i) {
      for (int a = 0; a < 3; ++a) x[4u * i + a] = random_coordinate(&rng, b, a);
      x[4u * i + 3] = uniform(&rng, -1e6f, 1e6f);  // lane 3 is ignored
    }
    for (uint32_t i = 0; i < count; ++i, ++runs) inside += check_voxel(b, x + 4u * i, &mismatches) ? 1u : 0u;
  }
  MESSAGE("field voxels compared: " << runs << ", inside: " << inside);
  CHECK(inside > runs / 16u);  // about one in ten
  CHECK(inside < runs);
  CHECK(mismatches == 0u);
}

TEST_CASE("nearest kernels: field voxel edge cases") {
  k::FieldBox b = {};
  b.lo[0] = -1.0f, b.lo[1] = 0.0f, b.lo[2] = 2.5f;
  b.dims[0] = 4.0f, b.dims[1] = 1.0f, b.dims[2] = 3.0f, b.dims[3] = 1.0f;
  b.cell = 0.5f;
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float tiny = std::numeric_limits<float>::denorm_min();
  uint32_t mismatches = 0;
  struct Case {
    float x[4];
    bool inside;
  };
  const Case cases[] = {
      {{-1.0f, 0.0f, 2.5f, 0.0f}, true},    // the low corner itself
      {{1.0f, 0.25f, 3.0f, nan}, false},    // on the high face of x
      {{0.75f, 0.25f, 3.0f, inf}, true},    // voxel (3, 0, 1)
      {{-1.0f, -tiny, 2.5f, 0.0f}, false},  // one subnormal below the corner
      {{-1.0f, tiny, 2.5f, 0.0f}, true},   {{-1.0f, -0.0f, 2.5f, 0.0f}, true},  // -0 at the corner: t = 0
      {{nan, 0.25f, 3.0f, 0.0f}, false},   {{0.0f, 0.25f, inf, 0.0f}, false},
      {{0.0f, -inf, 3.0f, 0.0f}, false},   {{0.25f, 0.4999f, 3.9999f, -inf}, true},
  };
  for (const Case& c : cases) {
    CAPTURE(c.x[0]);
    CAPTURE(c.x[1]);
    CAPTURE(c.x[2]);
    CHECK(check_voxel(b, c.x, &mismatches) == c.inside);
  }
  uint32_t v[4] = {};
  REQUIRE(k::field_voxel_reference(b, cases[2].x, v));
  CHECK(v[0] == 3u);
  CHECK(v[1] == 0u);
  CHECK(v[2] == 1u);
  CHECK(mismatches == 0u);
}

}  // namespace
}  // namespace spinhash
