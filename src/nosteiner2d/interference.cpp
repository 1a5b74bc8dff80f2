// Interfering faces of a (V, E) pair and their eligible parts; see
// interference.hpp.
//
// Minimisation along a piece (floating point, thesis §5.1 "Continuous
// spiral"). Along a segment not through V the polar angle phi is monotone, so
// min phi is at an end of the piece. For q = ln(rho / L) / phi: writing the
// supporting line as rho = d / cos(phi - phi0), the numerator
// N(phi) = ln(d / L) - ln cos(phi - phi0) is convex in phi, so every sublevel
// set {N - lambda phi <= 0} is an interval: q is quasiconvex in phi, hence in
// the (monotone) segment parameter t, and golden-section search finds its
// minimum on the piece (ends included).
#include "nosteiner2d/interference.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "nosteiner2d/exact_distance.hpp"

namespace pqmesh::detail {

namespace {

struct Interval {
  double lo = 0, hi = 1;
  bool empty = false;
};

Interval intersect(Interval x, Interval y) {
  Interval r{std::max(x.lo, y.lo), std::min(x.hi, y.hi), x.empty || y.empty};
  if (r.lo > r.hi) r.empty = true;
  return r;
}

// {t in [0,1] : f(t) >= 0} for f linear in t, given the exact signs of f at
// the ends and its floating values there (used only for the crossing).
Interval linear_clip(Sign sa, Sign sb, double fa, double fb) {
  const bool ina = sa != Sign::Negative, inb = sb != Sign::Negative;
  if (ina && inb) return {0, 1, false};
  if (!ina && !inb) return {0, 0, true};
  double t = (fa - fb != 0) ? fa / (fa - fb) : 0.5;
  if (!(t >= 0)) t = 0;
  if (t > 1) t = 1;
  return ina ? Interval{0, t, false} : Interval{t, 1, false};
}

// Exact: the closed segment ab meets the closed disk of centre c and radius
// |c u|. Used only when both ends lie outside the disk.
bool segment_meets_disk(Vec2 a, Vec2 b, Vec2 c, Vec2 u) {
  // The closest point of the line is interior to the segment iff both end
  // angles are acute; otherwise the closest point is an end (outside).
  if (dot_sign(a, c, b) != Sign::Positive || dot_sign(b, c, a) != Sign::Positive) return false;
  // Squared line distance: cross(b - a, c - a)^2 / |b - a|^2 <= |c - u|^2.
  const Vec2 d = b - a, w = c - a, cu = c - u;
  const double cr = cross(d, w), dd = dot(d, d), rr = dot(cu, cu);
  const double lhs = cr * cr, rhs = rr * dd;
  // Filter: the doubles carry relative error well below 1e-12 here; a wider
  // gap than 1e-9 decides, anything closer goes to the exact path.
  if (std::isfinite(lhs) && std::isfinite(rhs) && rhs > 1e-280) {
    if (lhs > rhs * (1 + 1e-9)) return false;
    if (lhs < rhs * (1 - 1e-9)) return true;
  }
  const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y), ux(u.x), uy(u.y);
  const mpq_class dx = bx - ax, dy = by - ay, wx = cx - ax, wy = cy - ay;
  const mpq_class crq = dx * wy - dy * wx;
  const mpq_class rq = (cx - ux) * (cx - ux) + (cy - uy) * (cy - uy);
  return crq * crq <= rq * (dx * dx + dy * dy);
}

Interval disk_clip(const SpiralFrame& fr, Vec2 a, Vec2 b) {
  const bool ina = compare_squared_distances(a, fr.V, fr.U, fr.V) != Sign::Positive;
  const bool inb = compare_squared_distances(b, fr.V, fr.U, fr.V) != Sign::Positive;
  if (ina && inb) return {0, 1, false};
  if (!ina && !inb && !segment_meets_disk(a, b, fr.V, fr.U)) return {0, 0, true};
  // Roots of |a - V + t (b - a)|^2 = L^2 (floating-point constructions).
  const Vec2 d = b - a, w = a - fr.V;
  const double qa = dot(d, d), qb = dot(w, d), qc = dot(w, w) - fr.length * fr.length;
  const double disc = std::max(0.0, qb * qb - qa * qc);
  const double sq = std::sqrt(disc);
  double lo = (-qb - sq) / qa, hi = (-qb + sq) / qa;
  lo = std::clamp(lo, 0.0, 1.0);
  hi = std::clamp(hi, 0.0, 1.0);
  if (ina) return {0, hi, false};
  if (inb) return {lo, 1, false};
  if (lo > hi) lo = hi = 0.5 * (lo + hi);  // touches: rounding only
  return {lo, hi, false};
}

Interval bisector_clip(const SpiralFrame& fr, Vec2 a, Vec2 b) {
  // f(t) = |W - U|^2 - |W - V|^2 is linear in t.
  const Sign sa = compare_squared_distances(a, fr.U, a, fr.V);
  const Sign sb = compare_squared_distances(b, fr.U, b, fr.V);
  const double fa = dot(a - fr.U, a - fr.U) - dot(a - fr.V, a - fr.V);
  const double fb = dot(b - fr.U, b - fr.U) - dot(b - fr.V, b - fr.V);
  return linear_clip(sa, sb, fa, fb);
}

// Half-plane on the interior side of the ray V -> X (first = true: points w
// with oriented(V, X, w) >= 0) or before it (oriented(V, w, X) >= 0).
Interval ray_clip(const SpiralFrame& fr, Vec2 x, bool after, Vec2 a, Vec2 b) {
  const double hand = fr.ccw ? 1.0 : -1.0;
  const Vec2 dx = x - fr.V;
  if (after) {
    return linear_clip(fr.oriented(fr.V, x, a), fr.oriented(fr.V, x, b), hand * cross(dx, a - fr.V),
                       hand * cross(dx, b - fr.V));
  }
  return linear_clip(fr.oriented(fr.V, a, x), fr.oriented(fr.V, b, x), hand * cross(a - fr.V, dx),
                     hand * cross(b - fr.V, dx));
}

double q_of(const SpiralFrame& fr, Vec2 w) {
  const double rho = norm(w - fr.V);
  double p = fr.phi(w);
  if (!(p > 0)) p = std::numeric_limits<double>::min();
  return std::log(rho / fr.length) / p;
}

}  // namespace

bool eligible_vertex(const SpiralFrame& fr, Vec2 w) {
  return compare_squared_distances(w, fr.V, fr.U, fr.V) != Sign::Positive &&
         compare_squared_distances(w, fr.V, w, fr.U) != Sign::Positive && fr.in_sector(w);
}

std::vector<SidePiece> eligible_pieces(const SpiralFrame& fr, Vec2 a, Vec2 b) {
  std::vector<SidePiece> out;
  const Interval base = intersect(disk_clip(fr, a, b), bisector_clip(fr, a, b));
  if (base.empty) return out;
  auto add = [&](Interval s) {
    const Interval r = intersect(base, s);
    if (!r.empty) out.push_back({r.lo, r.hi});
  };
  const Interval h1 = ray_clip(fr, fr.U, true, a, b);   // phi >= 0 side of E's line
  const Interval h2 = ray_clip(fr, fr.F, false, a, b);  // phi <= alpha side of F's line
  if (fr.turn == Sign::Positive) {
    add(intersect(h1, h2));
  } else if (fr.turn == Sign::Zero) {
    add(h1);
  } else {
    add(h1);
    add(h2);
  }
  return out;
}

PieceStart piece_start(const SpiralFrame& fr, Vec2 a, Vec2 b, SidePiece piece) {
  const Vec2 d = b - a;
  auto at = [&](double t) { return a + t * d; };
  PieceStart m;
  const Vec2 p0 = at(piece.t0), p1 = at(piece.t1);
  const double f0 = fr.phi(p0), f1 = fr.phi(p1);
  m.min_phi_point = f0 <= f1 ? p0 : p1;
  m.min_phi = std::min(f0, f1);
  // Lower bound on q: ln(rho_min / L) / phi_min, with rho_min the distance
  // from V to the piece (ln < 0 there, and every point has rho >= rho_min and
  // phi >= phi_min).
  const double dd = dot(d, d);
  double tc = dd > 0 ? dot(fr.V - a, d) / dd : piece.t0;
  tc = std::clamp(tc, piece.t0, piece.t1);
  const double rho_min = norm(at(tc) - fr.V);
  if (!(rho_min < fr.length)) {
    m.q_lower = std::numeric_limits<double>::infinity();
    return m;
  }
  m.q_lower = std::log(rho_min / fr.length) / std::max(m.min_phi, std::numeric_limits<double>::min());
  return m;
}

bool piece_min_q(const SpiralFrame& fr, Vec2 a, Vec2 b, SidePiece piece, Vec2& point, double& q_out) {
  const Vec2 d = b - a;
  auto at = [&](double t) { return a + t * d; };
  // Golden-section search for the minimum of the quasiconvex q on [t0, t1].
  // q is flat (quadratic) at an interior minimum, so a parameter resolution
  // of 1e-10 of the side leaves an error far below rounding in q; a minimum
  // at an end is taken from the ends, evaluated separately.
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = piece.t0, hi = piece.t1;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double q1 = q_of(fr, at(x1)), q2 = q_of(fr, at(x2));
  while (hi - lo > 1e-10) {
    if (q1 <= q2) {
      hi = x2;
      x2 = x1;
      q2 = q1;
      x1 = hi - g * (hi - lo);
      q1 = q_of(fr, at(x1));
    } else {
      lo = x1;
      x1 = x2;
      q1 = q2;
      x2 = lo + g * (hi - lo);
      q2 = q_of(fr, at(x2));
    }
  }
  double best_t = q1 <= q2 ? x1 : x2, best_q = std::min(q1, q2);
  for (const double t : {piece.t0, piece.t1}) {
    const double q = q_of(fr, at(t));
    if (q < best_q) best_q = q, best_t = t;
  }
  if (!(best_q < 0)) return false;
  q_out = best_q;
  point = at(best_t);
  return true;
}

}  // namespace pqmesh::detail
