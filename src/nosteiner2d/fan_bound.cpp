// The vertex fan bound; see fan_bound.hpp and docs/algorithm/nosteiner2d.md
// "The fan bound" for the proof.
#include "nosteiner2d/fan_bound.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "nosteiner2d/face_grid.hpp"
#include "nosteiner2d/sector_obstacles.hpp"
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

// Whether a fan from a side of length L can reach the direction omega of an
// obstacle at distance r with min angle A, log_ratio = ln(L / r): m full
// triangles (angles >= A) and a part psi >= 0 of the next one span at most
// m h_A(x_j) + h_A(psi); concave h_A with h_A(0) = 0 makes the equal split
// over m + 1 parts best while omega / (m + 1) >= A (increasing in m), else
// full triangles at A and psi = omega - m A. Only m = floor(omega / A) - 1
// (equal split) and m = floor(omega / A) (parts at A) need evaluating.
bool obstacle_feasible(double omega, double a, double log_ratio) {
  const double h_a = std::log(std::sin(2 * a) / std::sin(a));
  const double m = std::floor(omega / a);
  if (m >= 1 && span(omega, a, m) >= log_ratio) return true;  // m parts of omega / m >= A
  const double rest = std::max(0.0, omega - m * a);
  return m * h_a + std::log(std::sin(rest + a) / std::sin(a)) >= log_ratio;
}

}  // namespace

double obstacle_fan_bound(double omega, double ratio) {
  const double log_ratio = std::log(std::max(ratio, 1.0));
  double lo = 0, hi = std::numbers::pi / 3;
  if (obstacle_feasible(omega, hi, log_ratio)) return hi;
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid > 0 && obstacle_feasible(omega, mid, log_ratio))
      lo = mid;
    else
      hi = mid;
  }
  return hi;
}

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
  out.obstacle_angle = std::numbers::pi / 3;
  const FaceGrid grid(domain);
  std::vector<int> side_ids, vertex_ids;
  for (int l = 0; l < static_cast<int>(domain.loops.size()); ++l) {
    const int n = static_cast<int>(domain.loops[static_cast<std::size_t>(l)].size());
    for (int k = 0; k < n; ++k) {
      const SpiralFrame fr = make_frame(domain, l, k, true);
      const double l1 = fr.length, l2 = norm(fr.F - fr.V);
      const double a = fan_bound(fr.alpha, std::max(l1, l2) / std::min(l1, l2));
      if (a < out.angle) out.angle = a, out.vertex = fr.v;
      // Obstacles: vertices q of dP in the closed sector closer to V than the side E
      // (both frames: the fan from either side).
      for (const bool ccw : {true, false}) {
        const SpiralFrame e = make_frame(domain, l, k, ccw);
        for_each_sector_obstacle(domain, grid, e, side_ids, vertex_ids, [&](int q, Vec2 Q, double r) {
          const double b = obstacle_fan_bound(e.phi(Q), e.length / r);
          if (b < out.obstacle_angle) out.obstacle_angle = b, out.obstacle_vertex = e.v, out.obstacle = q;
          return true;
        });
      }
    }
  }
  return out;
}

}  // namespace pqmesh::detail
