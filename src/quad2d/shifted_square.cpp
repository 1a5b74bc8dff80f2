// Exact geometry against the shifted square (shifted_square.hpp).
#include "quad2d/shifted_square.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <gmpxx.h>

#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::quad2d::detail {
namespace {

int isign(Sign s) { return static_cast<int>(s); }
int dsign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// Corner k of the shifted square is c_k + (sx e, sy e^2), k counter-clockwise
// from the lo corner. orient2d(a, b, corner) = orient2d(a, b, c_k)
//   + det(b - a, (sx e, sy e^2)) = O + dx sy e^2 - dy sx e.
// The first non-zero term decides; since b != a it is never zero.
constexpr std::array<int, 4> kSx{-1, 1, 1, -1};
constexpr std::array<int, 4> kSy{-1, -1, 1, 1};

Vec2 corner(const Box& b, int k) {
  switch (k) {
    case 0: return {b.xlo, b.ylo};
    case 1: return {b.xhi, b.ylo};
    case 2: return {b.xhi, b.yhi};
    default: return {b.xlo, b.yhi};
  }
}

int orient_corner(Vec2 a, Vec2 c, const Box& b, int k) {
  const int o = isign(orient2d(a, c, corner(b, k)));
  if (o != 0) return o;
  const int dy = dsign(c.y - a.y), dx = dsign(c.x - a.x);  // sign of a double difference is exact
  if (dy != 0) return -dy * kSx[k];
  return dx * kSy[k];
}

// Does the directed edge a -> c cross side s of the shifted square? Proper
// crossing: a and c strictly on opposite sides of the side line (never on it
// after the shift) and the side's two perturbed corners strictly on opposite
// sides of the edge line. Returns 0 (no), +1 (enters), -1 (leaves).
int side_crossing(Vec2 a, Vec2 c, const Box& b, int s) {
  const bool ha = in_half(a, s, b), hc = in_half(c, s, b);
  if (ha == hc) return 0;
  if (orient_corner(a, c, b, s) == orient_corner(a, c, b, (s + 1) % 4)) return 0;
  return ha ? -1 : 1;
}

mpq_class q(double v) { return mpq_class(v); }

// Coordinate along the line of the crossing of segment a-c with the line
// {y = c0} (horizontal) or {x = c0} (vertical); the segment must straddle it.
mpq_class crossing_coordinate(Vec2 a, Vec2 c, bool horizontal, double c0) {
  if (horizontal) return q(a.x) + (q(c0) - q(a.y)) * (q(c.x) - q(a.x)) / (q(c.y) - q(a.y));
  return q(a.y) + (q(c0) - q(a.x)) * (q(c.y) - q(a.y)) / (q(c.x) - q(a.x));
}

// Derivative of that coordinate with respect to c0.
mpq_class crossing_slope(Vec2 a, Vec2 c, bool horizontal) {
  if (horizontal) return (q(c.x) - q(a.x)) / (q(c.y) - q(a.y));
  return (q(c.y) - q(a.y)) / (q(c.x) - q(a.x));
}

int cmp_q(const mpq_class& u, const mpq_class& v) {
  const int r = cmp(u, v);
  return r > 0 ? 1 : (r < 0 ? -1 : 0);
}

// Sign of (crossing coordinate of segment a-c with the line at c0) - v, by
// one orient2d with the point of the line at coordinate v: for an upward
// edge, (v, c0) lies on its left iff v < x; for a rightward edge, (c0, v)
// lies on its left iff v > y.
int cmp_crossing_value(Vec2 a, Vec2 c, bool horizontal, double c0, double v) {
  if (horizontal) return isign(orient2d(a, c, {v, c0})) * dsign(c.y - a.y);
  return -isign(orient2d(a, c, {c0, v})) * dsign(c.x - a.x);
}

// Double approximation of the crossing coordinate and a bound on its error:
// x = a.x + (c0 - a.y) * (dx / dy) takes 6 rounded operations, so
// |x - fl(x)| <= 8 u (|a.x| + |t|) with t the product term (u = 2^-53,
// generous constant); the filter below doubles that margin again. The bound
// assumes no overflow or underflow: err is +inf (use the exact path) unless
// every input is below 2^500 in magnitude and the quotient and product are
// zero or above 2^-500.
double approx_crossing(Vec2 a, Vec2 c, bool horizontal, double c0, double& err) {
  const double big = 0x1p500, small = 0x1p-500;
  const double base = horizontal ? a.x : a.y;
  const double off = horizontal ? c0 - a.y : c0 - a.x;  // differences of doubles: no underflow error
  const double num = horizontal ? c.x - a.x : c.y - a.y;
  const double den = horizontal ? c.y - a.y : c.x - a.x;
  const double quot = num / den;
  const double t = off * quot;
  const bool ok = std::abs(a.x) < big && std::abs(a.y) < big && std::abs(c.x) < big && std::abs(c.y) < big &&
                  std::abs(c0) < big && (num == 0 || std::abs(quot) > small) && (t == 0 || std::abs(t) > small) &&
                  (off == 0 || quot == 0 || t != 0);
  err = ok ? 8.0 * 0x1p-53 * (std::abs(base) + std::abs(t)) : HUGE_VAL;
  return base + t;
}

}  // namespace

// Compare the crossings of segments 1 and 2 with the line at c0 + sgn * eps
// (eps infinitesimal): the value at c0 first (a floating-point filter with a
// proven error bound, else GMP rationals), then the derivative (exact).
int cmp_on_line(Vec2 a1, Vec2 c1, Vec2 a2, Vec2 c2, bool horizontal, double c0, int sgn) {
  double e1 = 0, e2 = 0;
  const double x1 = approx_crossing(a1, c1, horizontal, c0, e1), x2 = approx_crossing(a2, c2, horizontal, c0, e2);
  const double margin = 2.0 * (e1 + e2) + 2.0 * 0x1p-53 * (std::abs(x1) + std::abs(x2));
  if (std::isfinite(margin) && std::abs(x1 - x2) > margin) return x1 > x2 ? 1 : -1;
  const int r = cmp_q(crossing_coordinate(a1, c1, horizontal, c0), crossing_coordinate(a2, c2, horizontal, c0));
  if (r != 0) return r;
  return sgn * cmp_q(crossing_slope(a1, c1, horizontal), crossing_slope(a2, c2, horizontal));
}

// Crossing of the directed edge with the side line, as a parameter along ∂C
// (a construction for reports; clamped into the side).
double crossing_t(Vec2 a, Vec2 c, const Box& b, int s) {
  const double len = b.xhi - b.xlo;
  const auto at_y = [&](double y) { return std::clamp(a.x + (y - a.y) * (c.x - a.x) / (c.y - a.y), b.xlo, b.xhi); };
  const auto at_x = [&](double x) { return std::clamp(a.y + (x - a.x) * (c.y - a.y) / (c.x - a.x), b.ylo, b.yhi); };
  switch (s) {
    case 0: return at_y(b.ylo) - b.xlo;
    case 1: return len + (at_x(b.xhi) - b.ylo);
    case 2: return 2 * len + (b.xhi - at_y(b.yhi));
    default: return 3 * len + (b.yhi - at_x(b.xlo));
  }
}

EdgeCrossings crossings_of(Vec2 a, Vec2 c, const Box& b) {
  EdgeCrossings r;
  for (int s = 0; s < 4; ++s) {
    const int d = side_crossing(a, c, b, s);
    if (d == 0) continue;
    if (r.count == 2) throw InternalError("quad2d: a segment crosses a square more than twice");
    r.side[static_cast<std::size_t>(r.count)] = s;
    r.dir[static_cast<std::size_t>(r.count)] = d;
    ++r.count;
  }
  if (r.count == 2 && r.dir[0] < r.dir[1]) {
    std::swap(r.side[0], r.side[1]);
    std::swap(r.dir[0], r.dir[1]);
  }
  if (r.count == 2 && r.dir[0] == r.dir[1]) throw InternalError("quad2d: a segment enters a square twice");
  return r;
}

bool meets(Vec2 a, Vec2 c, const Box& b) {
  if (inside(a, b) || inside(c, b)) return true;
  for (int s = 0; s < 4; ++s)
    if (side_crossing(a, c, b, s) != 0) return true;
  return false;
}

// Crossing parity of the ray from the perturbed lo corner (xlo - e, ylo - e^2)
// in +x with every edge of P: is that corner inside P?
bool corner_in_domain(const Domain2& d, const Box& b) {
  bool in = false;
  for (std::size_t l = 0; l < d.loops.size(); ++l) {
    for (std::size_t k = 0; k < d.loops[l].size(); ++k) {
      const EdgeGeom g = geom(d, {static_cast<int>(l), static_cast<int>(k)});
      // y > ylo - e^2  <=>  y >= ylo
      const bool ua = g.a.y >= b.ylo, uc = g.c.y >= b.ylo;
      if (ua == uc) continue;
      const int dy = dsign(g.c.y - g.a.y);
      // The crossing is right of the point iff the point is left of the upward edge.
      if (orient_corner(g.a, g.c, b, 0) == dy) in = !in;
    }
  }
  return in;
}

// The first edge hit by the ray {(x, p.y + d) : x > p.x}, d infinitesimal
// (d << e^2), before it leaves the shifted square through the right side.
// Edges of loop skip_loop are ignored.
std::optional<std::size_t> first_hit(const Domain2& d, const Box& b, Vec2 p,
                                     const std::vector<std::pair<LoopEdge, int>>& edges, int skip_loop) {
  std::optional<std::size_t> best;
  EdgeGeom best_g{};
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (edges[i].first.loop == skip_loop) continue;
    const EdgeGeom g = geom(d, edges[i].first);
    if ((g.a.y > p.y) == (g.c.y > p.y)) continue;
    const int rp = cmp_crossing_value(g.a, g.c, true, p.y, p.x);
    if (rp < 0) continue;
    if (rp == 0 && dsign(g.c.x - g.a.x) * dsign(g.c.y - g.a.y) <= 0) continue;
    if (cmp_crossing_value(g.a, g.c, true, p.y, b.xhi) > 0) continue;  // x <= xhi  =>  x + O(d) < xhi + e
    if (!best || cmp_on_line(g.a, g.c, best_g.a, best_g.c, true, p.y, 1) < 0) {
      best = i;
      best_g = g;
    }
  }
  return best;
}

// The first crossing counter-clockwise after the point (xhi + e, p.y + d) on
// the right side (sorted crossings; wraps to 0).
std::size_t crossing_after_right_point(const Domain2& d, const Box& b, Vec2 p,
                                       const std::vector<Crossing>& crossings) {
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const auto& c = crossings[i];
    if (c.side < 1) continue;
    if (c.side > 1) return i;
    const EdgeGeom g = geom(d, c.edge);
    // crossing height at x = xhi + e is y(xhi) + e * dy/dx
    const int r = cmp_crossing_value(g.a, g.c, false, b.xhi, p.y);
    if (r > 0) return i;
    if (r < 0) continue;
    if (dsign(g.c.y - g.a.y) * dsign(g.c.x - g.a.x) > 0) return i;
  }
  return 0;
}

}  // namespace pqmesh::quad2d::detail
