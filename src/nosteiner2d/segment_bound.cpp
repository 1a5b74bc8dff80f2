// The segment-triangle bound; see segment_bound.hpp and
// docs/algorithm/nosteiner2d.md "The segment bound" for the proof.
#include "nosteiner2d/segment_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "nosteiner2d/face_grid.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

double segment_apex_angle(Vec2 a, Vec2 b, Vec2 q) {
  const Vec2 u = b - a, va = q - a, vb = q - b;
  const double at_a = std::atan2(cross(u, va), dot(u, va));
  const double at_b = std::atan2(cross(u, vb), -dot(u, vb));
  return std::max(at_a, at_b);
}

namespace {

// The crossing of side cd with the perpendicular bisector of ab, when it is
// strictly inside cd and well left of a -> b, with the angle t there made
// safe against the rounding of the construction: the computed q is within
// 2^-50 s of a true point q' of cd (s the largest coordinate magnitude), so
// with q's height h above ab at least 2^-44 s, q' is left of ab too and
// t(q') <= t(q) + 2^-48 s / h (a point moved by d changes the angles at a and
// b by at most d / h). Returns that safe value, or +infinity.
double bisector_crossing(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Vec2& q) {
  const double none = std::numeric_limits<double>::infinity();
  const Vec2 u = b - a, mid = {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  const double den = dot(d - c, u);
  if (den == 0) return none;
  const double t = dot(mid - c, u) / den;
  if (!(t > 0 && t < 1)) return none;
  q = c + t * (d - c);
  const double scale = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y), std::abs(c.x),
                                 std::abs(c.y), std::abs(d.x), std::abs(d.y)});
  const double h = cross(u, q - a) / norm(u);
  if (!(h > std::ldexp(scale, -44))) return none;
  return segment_apex_angle(a, b, q) + std::ldexp(scale, -48) / h;
}

}  // namespace

SegmentBound segment_bound(const Domain2& domain) {
  const auto& P = domain.pslg.vertices;
  const FaceGrid grid(domain);
  const double cap = std::numbers::pi / 3;
  SegmentBound out;
  out.angle = cap;
  std::vector<int> side_ids, vertex_ids;
  for (int l = 0; l < static_cast<int>(domain.loops.size()); ++l) {
    const auto& loop = domain.loops[static_cast<std::size_t>(l)];
    const int n = static_cast<int>(loop.size());
    out.side_angle.emplace_back(static_cast<std::size_t>(n), cap);
    for (int k = 0; k < n; ++k) {
      const Vec2 a = P[static_cast<std::size_t>(loop[k])], b = P[static_cast<std::size_t>(loop[(k + 1) % n])];
      const Vec2 u = b - a, left = {-u.y, u.x};
      // Bounding square of the equilateral triangle on ab (left side).
      const Vec2 centre = a + 0.5 * u + (std::sqrt(3.0) / 4) * left;
      grid.query(centre, 0.5 * norm(u), side_ids, vertex_ids);
      double best = cap;
      Vec2 witness{};
      auto consider = [&](double t, Vec2 q) {
        if (t < best) best = t, witness = q;
      };
      for (const int v : vertex_ids) {
        const Vec2 q = P[static_cast<std::size_t>(grid.vertices()[static_cast<std::size_t>(v)])];
        if (orient2d(a, b, q) == Sign::Positive) consider(segment_apex_angle(a, b, q), q);
      }
      const int ia = loop[k], ib = loop[(k + 1) % n];
      for (const int s : side_ids) {
        const auto& cd = grid.sides()[static_cast<std::size_t>(s)];
        // A side at a (or b) gives angle qab = alpha_a (or alpha_b) all along: the alpha term.
        if (cd[0] == ia || cd[0] == ib || cd[1] == ia || cd[1] == ib) continue;
        const Vec2 c = P[static_cast<std::size_t>(cd[0])], d = P[static_cast<std::size_t>(cd[1])];
        // Both ends right of or on line ab: the whole side is (no point in H).
        if (orient2d(a, b, c) != Sign::Positive && orient2d(a, b, d) != Sign::Positive) continue;
        Vec2 q;
        const double t = bisector_crossing(a, b, c, d, q);
        consider(t, q);
      }
      out.side_angle.back()[static_cast<std::size_t>(k)] = best;
      if (best < out.angle) out.angle = best, out.loop = l, out.side = k, out.witness = witness;
    }
  }
  return out;
}

}  // namespace pqmesh::detail
