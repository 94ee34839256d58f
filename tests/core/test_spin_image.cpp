// Spin images of a plane and of a sphere against bins computed by hand.
#include <doctest/doctest.h>

#include <vector>

#include "descriptor/spin_image.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/grid_fixture.hpp"

using namespace spinhash;

namespace {

using test::GridFixture;

SpinImageParams paper_params() {  // 1 m support, 10 x 10 bins
  SpinImageParams sp;
  sp.radius = 1.0f;
  sp.bins_alpha = 10;
  sp.bins_beta = 10;
  sp.use_support_angle = false;
  return sp;
}

}  // namespace

TEST_CASE("a single vote splits bilinearly between the nearest bin centres") {
  SpinImageParams sp = paper_params();
  float img[100] = {};
  // alpha 0.25 is the centre of alpha bin 2; beta 0 lies between beta bins 4 and 5.
  spin_vote(sp, 0.25f, 0.0f, img);
  CHECK(img[4 * 10 + 2] == doctest::Approx(0.5f));
  CHECK(img[5 * 10 + 2] == doctest::Approx(0.5f));
  float img2[100] = {};
  // alpha 0.30 is half way from centre 2 (0.25) to 3 (0.35); beta -0.6 half
  // way between the centres of rows 1 (-0.7) and 2 (-0.5).
  spin_vote(sp, 0.30f, -0.6f, img2);
  for (int idx : {1 * 10 + 2, 1 * 10 + 3, 2 * 10 + 2, 2 * 10 + 3}) CHECK(img2[idx] == doctest::Approx(0.25f));
}

TEST_CASE("spin image of a plane: beta rows 4 and 5 only, alpha mass growing with the ring area") {
  std::vector<float> pts = test::plane_grid(1.2f, 0.01f);
  std::vector<float> normals(pts.size(), 0.0f);
  for (size_t i = 2; i < normals.size(); i += 3) normals[i] = 1.0f;
  std::vector<uint8_t> has(pts.size() / 3, 1);
  GridFixture g(pts, 0.5f);
  float p[3] = {0, 0, 0}, n[3] = {0, 0, 1}, img[100];
  compute_spin_image(paper_params(), g.grid, pts.data(), normals.data(), has.data(), p, n, img);
  // Uniform density: a triangle kernel at centre c_i collects 2 c_i b / R^2 of
  // the disc for interior bins; the clamped rims collect 0.010833 and 0.189167.
  float expected_alpha[10] = {0.010833f, 0.03f, 0.05f, 0.07f, 0.09f, 0.11f, 0.13f, 0.15f, 0.17f, 0.189167f};
  for (int i = 0; i < 10; ++i) {
    CHECK(img[4 * 10 + i] == doctest::Approx(expected_alpha[i] / 2).epsilon(0.02));
    CHECK(img[5 * 10 + i] == doctest::Approx(expected_alpha[i] / 2).epsilon(0.02));
    for (int row : {0, 1, 2, 3, 6, 7, 8, 9}) CHECK(img[row * 10 + i] == 0.0f);
  }
}

TEST_CASE("spin image of a sphere seen from its top: uniform in beta (Archimedes), nothing above") {
  // Sphere of radius 0.5 touching the basis point from below: every point is
  // within R = 1, and area is uniform in height, so beta is uniform on [-1, 0].
  std::vector<float> pts = test::fibonacci_sphere(40000, 0.5f, 0.0f, 0.0f, -0.5f);
  std::vector<float> normals = test::sphere_normals(pts, 0.0f, 0.0f, -0.5f);
  std::vector<uint8_t> has(pts.size() / 3, 1);
  GridFixture g(pts, 0.5f);
  float p[3] = {0, 0, 0}, n[3] = {0, 0, 1}, img[100];
  compute_spin_image(paper_params(), g.grid, pts.data(), normals.data(), has.data(), p, n, img);
  // Rows are 0.2 m of beta; the bilinear kernel over a uniform density gives
  // 0.2 per full row, the top rows split 0.175 / 0.025 at beta = 0.
  float expected_rows[10] = {0.2f, 0.2f, 0.2f, 0.2f, 0.175f, 0.025f, 0, 0, 0, 0};
  for (int row = 0; row < 10; ++row) {
    float sum = 0;
    for (int i = 0; i < 10; ++i) sum += img[row * 10 + i];
    CHECK(sum == doctest::Approx(expected_rows[row]).epsilon(0.03).scale(1.0));
  }
  // alpha <= 0.5 everywhere (the sphere's radius): alpha bins 6..9 are empty.
  for (int row = 0; row < 10; ++row)
    for (int i = 6; i < 10; ++i) CHECK(img[row * 10 + i] == 0.0f);
}

TEST_CASE("the support angle drops neighbours facing away") {
  std::vector<float> pts = test::fibonacci_sphere(20000, 0.5f, 0.0f, 0.0f, -0.5f);
  std::vector<float> normals = test::sphere_normals(pts, 0.0f, 0.0f, -0.5f);
  std::vector<uint8_t> has(pts.size() / 3, 1);
  GridFixture g(pts, 0.5f);
  SpinImageParams sp = paper_params();
  sp.use_support_angle = true;
  sp.cos_support_angle = 0.5f;  // 60 degrees: normal z >= 0.5 <=> beta >= -0.25
  float p[3] = {0, 0, 0}, n[3] = {0, 0, 1}, img[100];
  compute_spin_image(sp, g.grid, pts.data(), normals.data(), has.data(), p, n, img);
  for (int row = 0; row < 3; ++row)  // beta < -0.5: all facing away
    for (int i = 0; i < 10; ++i) CHECK(img[row * 10 + i] == 0.0f);
}

TEST_CASE("quantisation rounds, saturates and keeps zeros") {
  float img[4] = {0.0f, 0.01f, 0.5f, 0.0049f};
  uint8_t q[4];
  quantize_spin(img, 4, 100.0f, q);
  CHECK(q[0] == 0);
  CHECK(q[1] == 1);
  CHECK(q[2] == 50);
  CHECK(q[3] == 0);
  quantize_spin(img, 4, 1000.0f, q);
  CHECK(q[2] == 255);
}
