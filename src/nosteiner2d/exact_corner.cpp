// Exact corner tests for §5.2 (see exact_corner.hpp): GMP rationals on the
// binary values of the doubles; called once per Q vertex and R side.
#include "nosteiner2d/exact_corner.hpp"

#include <gmpxx.h>

namespace pqmesh::detail {

namespace {
Sign sign_of_mpq(const mpq_class& v) {
  const int s = sgn(v);
  return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}
}  // namespace

bool angle_at_most_three_quarter_pi(Vec2 prev, Vec2 v, Vec2 next) {
  if (orient2d(v, next, prev) != Sign::Positive) return false;  // angle >= pi
  const mpq_class vx(v.x), vy(v.y);
  const mpq_class bx = mpq_class(next.x) - vx, by = mpq_class(next.y) - vy;
  const mpq_class ax = mpq_class(prev.x) - vx, ay = mpq_class(prev.y) - vy;
  const mpq_class value = bx * ax + by * ay + (bx * ay - by * ax);
  return sgn(value) >= 0;
}

Sign dot_sign_directions(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const mpq_class ux = mpq_class(b.x) - mpq_class(a.x), uy = mpq_class(b.y) - mpq_class(a.y);
  const mpq_class wx = mpq_class(d.x) - mpq_class(c.x), wy = mpq_class(d.y) - mpq_class(c.y);
  return sign_of_mpq(ux * wx + uy * wy);
}

}  // namespace pqmesh::detail
