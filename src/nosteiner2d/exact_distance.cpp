// Exact squared-distance comparison: filtered double, GMP fallback.
#include "nosteiner2d/exact_distance.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>

namespace pqmesh::detail {

namespace {

Sign exact_compare(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y), dx(d.x), dy(d.y);
  const mpq_class ux = ax - bx, uy = ay - by, vx = cx - dx, vy = cy - dy;
  const mpq_class value = ux * ux + uy * uy - vx * vx - vy * vy;
  const int s = sgn(value);
  return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace

Sign compare_squared_distances(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double ux = a.x - b.x, uy = a.y - b.y, vx = c.x - d.x, vy = c.y - d.y;
  const double p = ux * ux + uy * uy, q = vx * vx + vy * vy;
  const double value = p - q;
  // Each difference carries relative error <= u (u = 2^-53), each square
  // <= 3u, each sum one more u: |error| <= 6u (p + q) plus the final
  // subtraction's u |value|; 8 * 2^-52 (p + q) is a safe over-estimate. Tiny
  // magnitudes (underflow) and non-finite values go to the exact path.
  const double bound = 8.0 * std::numeric_limits<double>::epsilon() * (p + q);
  if (std::isfinite(value) && (p + q) > 1e-280 && std::abs(value) > bound) return sign_of(value);
  return exact_compare(a, b, c, d);
}

}  // namespace pqmesh::detail
