// Doublets (section 7, Figure 5): two oriented points seen as a shape that a
// rigid motion preserves: d = |p2 - p1|, a = angle(n1, n2), b = angle(n1, u),
// c = angle(n2, u) with u = (p2 - p1) / d. d, a, b, c are also preserved by a
// mirror image, so the cascade adds the handedness t = (n1 x n2) . u, which a
// reflection negates. Checks run cheapest first and stop at the first failure.
#pragma once
#include <cmath>
#include <cstdint>

#include "match/oriented_point.hpp"

namespace spinhash {

struct DoubletShape {
  float d = 0.0f;  // m
  float a = 0.0f;  // radians
  float b = 0.0f;
  float c = 0.0f;
  float t = 0.0f;  // handedness, in [-1, 1]
};

struct DoubletTolerance {
  float distance = 0.3f;    // |d - d'|, m
  float angle = 0.44f;      // |a - a'|, |b - b'|, |c - c'|, radians
  float handedness = 0.5f;  // |t - t'|
};

enum class CascadeStage : uint8_t { kPass, kDistance, kAngleA, kAngleB, kAngleC, kHandedness, kDegenerate };

// false when the two points coincide (no direction u).
bool doublet_shape(const OrientedPoint& x1, const OrientedPoint& x2, DoubletShape* out);

// Stability constraints of eq. 3: d >= d_min and angle(n1, n2) >= theta_min.
inline bool is_stable(const DoubletShape& s, float d_min, float theta_min) {
  return s.d >= d_min && s.a >= theta_min;
}

// The cascade of Figure 5 for a query doublet against model points (m1, m2):
// the first constraint that fails, or kPass.
CascadeStage check_doublet(const DoubletShape& query, const OrientedPoint& m1, const OrientedPoint& m2,
                           const DoubletTolerance& tol);

// The cascade's first constraint reads the model points' separation d alone,
// so a caller can reject most pairs before it decodes their normals.
inline bool separation_agrees(const DoubletShape& query, float d, const DoubletTolerance& tol) {
  return !(std::fabs(d - query.d) > tol.distance);
}

// The rest of the cascade, for model points whose separation agrees:
// normals n1 and n2, delta = p2 - p1 and d = |delta|. check_doublet is
// separation_agrees, then this.
CascadeStage check_doublet_normals(const DoubletShape& query, const Eigen::Vector3f& n1,
                                   const Eigen::Vector3f& n2, const Eigen::Vector3f& delta, float d,
                                   const DoubletTolerance& tol);

}  // namespace spinhash
