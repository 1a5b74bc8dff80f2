#include "tet3d/points/edge_point.hpp"

#include <algorithm>
#include <cmath>

#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::tet3d {

std::pair<double, double> clip_segment(Vec3 a, Vec3 b, Vec3 lo, Vec3 hi) {
  double t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const double p = axis_coord(a, k), d = axis_coord(b, k) - p;
    if (d == 0) {
      if (p < axis_coord(lo, k) || p > axis_coord(hi, k)) return {1, 0};
      continue;
    }
    double s0 = (axis_coord(lo, k) - p) / d, s1 = (axis_coord(hi, k) - p) / d;
    if (s0 > s1) std::swap(s0, s1);
    t0 = std::max(t0, s0);
    t1 = std::min(t1, s1);
  }
  return {t0, t1};
}

Vec3 round_onto_segment(Vec3 a, Vec3 b, Vec3 m) {
  int d = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(axis_coord(b, k) - axis_coord(a, k)) > std::fabs(axis_coord(b, d) - axis_coord(a, d))) d = k;
  Vec3 p = m;
  const double dlo = std::min(axis_coord(a, d), axis_coord(b, d)), dhi = std::max(axis_coord(a, d), axis_coord(b, d));
  axis_ref(p, d) = std::clamp(axis_coord(m, d), dlo, dhi);
  const double x = axis_coord(p, d);
  const Sign dir = compare(axis_coord(b, d), axis_coord(a, d));
  for (int w = 0; w < 3; ++w) {
    if (w == d) continue;
    // sign(w* - y) for the segment's coordinate w* at x on axis d: the
    // segment's projection onto the (d, w) plane passes below / above (x, y).
    const Vec2 pa{axis_coord(a, d), axis_coord(a, w)}, pb{axis_coord(b, d), axis_coord(b, w)};
    auto rel = [&](double y) { return orient2d(pa, pb, {x, y}) * dir * Sign::Negative; };
    double lo = std::min(axis_coord(a, w), axis_coord(b, w)), hi = std::max(axis_coord(a, w), axis_coord(b, w));
    double best = lo;
    if (lo == hi) {
      best = lo;
    } else {
      // rel(lo) >= 0 >= rel(hi): w* in [lo, hi].
      for (int it = 0; it < 2200; ++it) {
        const double mid = lo + (hi - lo) / 2;
        if (mid == lo || mid == hi) break;
        const Sign s = rel(mid);
        if (s == Sign::Zero) {
          lo = mid;
          break;
        }
        (s == Sign::Positive ? lo : hi) = mid;
      }
      best = lo;
    }
    axis_ref(p, w) = best;
  }
  if (!within_ulp_of_segment(p, a, b)) throw InternalError("tet3d: a point does not round onto a P edge");
  return p;
}

}  // namespace pqmesh::tet3d
