#pragma once
// Independent exact oracles for the predicate tests: each sign evaluated in
// GMP rationals from the double inputs (every double is a rational, so the
// determinants are exact). They share no code with src/predicates, so a test
// comparing a stage with them checks it against the definition.
#include <gmpxx.h>

#include "predicates/predicates.hpp"

namespace pqmesh::test {

inline mpq_class exact(double v) { return mpq_class(v); }

// Sign of det(a - c, b - c) = det(b - a, c - a): orient2d(a, b, c).
inline Sign orient2d_oracle(Vec2 a, Vec2 b, Vec2 c) {
  const mpq_class acx = exact(a.x) - exact(c.x), bcx = exact(b.x) - exact(c.x);
  const mpq_class acy = exact(a.y) - exact(c.y), bcy = exact(b.y) - exact(c.y);
  return static_cast<Sign>(sgn(acx * bcy - acy * bcx));
}

// Sign of (b - a) . ((c - a) x (d - a)): orient3d(a, b, c, d).
inline Sign orient3d_oracle(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const auto q = exact;
  const mpq_class ux = q(b.x) - q(a.x), uy = q(b.y) - q(a.y), uz = q(b.z) - q(a.z);
  const mpq_class vx = q(c.x) - q(a.x), vy = q(c.y) - q(a.y), vz = q(c.z) - q(a.z);
  const mpq_class wx = q(d.x) - q(a.x), wy = q(d.y) - q(a.y), wz = q(d.z) - q(a.z);
  return static_cast<Sign>(sgn(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)));
}

// Sign of the lifted 3x3 determinant with d subtracted: incircle(a, b, c, d).
inline Sign incircle_oracle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const auto q = exact;
  const mpq_class ax = q(a.x) - q(d.x), ay = q(a.y) - q(d.y), bx = q(b.x) - q(d.x), by = q(b.y) - q(d.y);
  const mpq_class cx = q(c.x) - q(d.x), cy = q(c.y) - q(d.y);
  const mpq_class al = ax * ax + ay * ay, bl = bx * bx + by * by, cl = cx * cx + cy * cy;
  return static_cast<Sign>(sgn(al * (bx * cy - by * cx) + bl * (cx * ay - cy * ax) + cl * (ax * by - ay * bx)));
}

// Sign of (b - a) . (d - c): dot_sign(a, b, c, d) in 3D.
inline Sign dot_oracle(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const auto q = exact;
  return static_cast<Sign>(sgn((q(b.x) - q(a.x)) * (q(d.x) - q(c.x)) + (q(b.y) - q(a.y)) * (q(d.y) - q(c.y)) +
                               (q(b.z) - q(a.z)) * (q(d.z) - q(c.z))));
}

// Sign of (b - a) . (c - a): dot_sign(a, b, c) in 2D.
inline Sign dot_oracle(Vec2 a, Vec2 b, Vec2 c) {
  const auto q = exact;
  return static_cast<Sign>(sgn((q(b.x) - q(a.x)) * (q(c.x) - q(a.x)) + (q(b.y) - q(a.y)) * (q(c.y) - q(a.y))));
}

// Counts of each sign met, so a test can require that its inputs reached
// every outcome (positive, zero, negative).
struct SignTally {
  int positive = 0, zero = 0, negative = 0;
  void count(Sign s) {
    positive += s == Sign::Positive;
    zero += s == Sign::Zero;
    negative += s == Sign::Negative;
  }
};

}  // namespace pqmesh::test
