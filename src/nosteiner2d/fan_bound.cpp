// The vertex fan bound; see fan_bound.hpp and docs/algorithm/nosteiner2d.md
// "The fan bound" for the proof.
#include "nosteiner2d/fan_bound.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nosteiner2d/spiral_frame.hpp"

namespace pqmesh::detail {

namespace {

// k h_A(alpha / k), the largest ln R a fan of k equal steps with min angle A spans.
double span(double alpha, double a, double k) { return k * std::log(std::sin(alpha / k + a) / std::sin(a)); }

// Whether some integer k in [alpha / (pi - 2A), alpha / A] spans ln R. The
// span is concave in k (the perspective of the concave h_A), so an integer
// ternary search finds its maximum over the range.
bool feasible(double alpha, double a, double log_ratio) {
  const double lo_real = alpha / (std::numbers::pi - 2 * a), hi_real = alpha / a;
  double lo = std::ceil(lo_real), hi = std::floor(hi_real);
  lo = std::max(lo, 1.0);
  if (lo > hi) return false;
  while (hi - lo > 2) {
    const double m1 = std::floor(lo + (hi - lo) / 3), m2 = std::ceil(hi - (hi - lo) / 3);
    if (span(alpha, a, m1) < span(alpha, a, m2))
      lo = m1 + 1;
    else
      hi = m2 - 1;
    if (m1 >= m2) break;
  }
  for (double k = lo; k <= hi; k += 1)
    if (span(alpha, a, k) >= log_ratio) return true;
  return false;
}

}  // namespace

double fan_bound(double alpha, double ratio) {
  const double log_ratio = std::log(std::max(ratio, 1.0));
  // A* <= min(alpha, pi/3): k >= 1 needs A <= alpha / k <= pi - 2A.
  double lo = 0, hi = std::min(alpha, std::numbers::pi / 3);
  if (feasible(alpha, hi, log_ratio)) return hi;
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid > 0 && feasible(alpha, mid, log_ratio))
      lo = mid;
    else
      hi = mid;
  }
  return hi;  // infeasible (or the cap): an upper bound on A*
}

FanBound vertex_fan_bound(const Domain2& domain) {
  FanBound out;
  out.angle = std::numbers::pi / 3;
  for (int l = 0; l < static_cast<int>(domain.loops.size()); ++l) {
    const int n = static_cast<int>(domain.loops[static_cast<std::size_t>(l)].size());
    for (int k = 0; k < n; ++k) {
      const SpiralFrame fr = make_frame(domain, l, k, true);
      const double l1 = fr.length, l2 = norm(fr.F - fr.V);
      const double a = fan_bound(fr.alpha, std::max(l1, l2) / std::min(l1, l2));
      if (a < out.angle) out.angle = a, out.vertex = fr.v;
    }
  }
  return out;
}

}  // namespace pqmesh::detail
