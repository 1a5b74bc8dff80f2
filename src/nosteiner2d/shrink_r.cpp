// Thesis §5.2 "Shrinking the polygon Q to R" (Fig. 5.14).
//
// Every side E = p -> q of Q (interior on the left) gets the shrunk line
// { x : n_E . (x - p) = d_E }, n_E the unit left normal, d_E = delta(E)/4.
// At a Q vertex V with sides E_in = prev -> V and E_out = V -> next:
//  Case 1, interior angle <= 3 pi/4 (exact decision, exact_corner.hpp): one
//    R vertex, the intersection of the two shrunk lines (they meet: the angle
//    is in (0, 3 pi/4]).
//  Case 2, angle > 3 pi/4 (reflex and straight corners included): with t the
//    interior angle, counted counter-clockwise from V -> next, the rays at
//    t/2 - pi/4 ("pi/4 clockwise from the bisector") and t/2 + pi/4 meet the
//    shrunk lines of E_out and E_in at distance d / sin(beta) from V, where
//    beta = t/2 - pi/4 > pi/8 is the angle each ray makes with its side
//    (raised to kMinRayAngle, see there). The loop
//    passes the E_in point first, then the E_out point, and the R side
//    between them is the shrunk side for V.
// The tie t = 3 pi/4 is Case 1 (the thesis lists it in both cases).
// Constructions are floating point; the checks that R keeps the combinatorics
// of Q (every shrunk side points the way its Q side does, every Case 2 side
// turns around V the way the corner does) are exact on the rounded points.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "nosteiner2d/exact_corner.hpp"
#include "nosteiner2d/stages.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {

namespace {

struct Line {
  Vec2 n;    // unit normal, pointing into Q
  double c;  // n . x = c on the shrunk line
};

Line shrunk_line(Vec2 p, Vec2 q, double d) {
  const double len = std::hypot(q.x - p.x, q.y - p.y);
  const Vec2 n{-(q.y - p.y) / len, (q.x - p.x) / len};
  return {n, dot(n, p) + d};
}

Vec2 intersect(const Line& a, const Line& b) {
  const double det = a.n.x * b.n.y - a.n.y * b.n.x;
  return {(a.c * b.n.y - b.c * a.n.y) / det, (a.n.x * b.c - b.n.x * a.c) / det};
}

Vec2 rotate(Vec2 u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * u.x - s * u.y, s * u.x + c * u.y};
}

// A Case 2 point lies d_E cot(beta) along its side E from V, and
// d_E = delta(E)/4 <= L(E)/4 (delta(E) <= delta(V) <= |V, other end of E|).
// With the thesis's beta = t/2 - pi/4 > pi/8, cot(beta) < 2.414 and two Case 2
// ends can take 1.2 L(E) together: the shrunk side reverses (a weld side of
// Fig. 5.10 between two corners of ~0.79 pi in data/2d/square_holes did).
// cot(beta) <= 1.8 caps each end at 0.45 L(E). A Case 1 end with the angle
// t in [0.39 pi, 3 pi/4] (Theorem 26) takes d_E cot t + d_other / sin t
// <= (0.09 + 0.36) L(E) (d_other <= L(E)/4 likewise), so no shrunk side of Q
// can reverse; shrink_q_to_r still checks it exactly.
const double kMinRayAngle = std::atan2(1.0, 1.8);

}  // namespace

PolygonR shrink_q_to_r(const std::vector<std::vector<Vec2>>& q_loops) {
  PolygonR r;
  r.delta = polygon_delta(q_loops);
  std::ostringstream why;
  for (std::size_t l = 0; l < q_loops.size(); ++l) {
    const auto& lp = q_loops[l];
    const std::size_t n = lp.size();
    std::vector<Line> lines(n);
    for (std::size_t k = 0; k < n; ++k) {
      lines[k] = shrunk_line(lp[k], lp[(k + 1) % n], r.delta.side[l][k] / 4);
      if (!(r.delta.side[l][k] / 4 >= kRShrinkResolution * (std::abs(lp[k].x) + std::abs(lp[k].y))))
        r.representable = false;
    }
    auto& out = r.loops.emplace_back();
    auto& vsrc = r.vertex_source.emplace_back();
    auto& ssrc = r.side_source.emplace_back();
    auto& sdel = r.side_delta.emplace_back();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t kp = (k + n - 1) % n;
      const Vec2 prev = lp[kp], v = lp[k], next = lp[(k + 1) % n];
      if (detail::angle_at_most_three_quarter_pi(prev, v, next)) {  // Case 1
        ++r.case1;
        out.push_back(intersect(lines[kp], lines[k]));
        vsrc.push_back(int(k));
        ssrc.push_back(int(k));
        sdel.push_back(r.delta.side[l][k]);
      } else {  // Case 2
        ++r.case2;
        const Vec2 b = next - v, a = prev - v;
        double t = std::atan2(cross(b, a), dot(b, a));  // interior angle, ccw from b to a
        if (t <= 0) t += 2 * std::numbers::pi;
        // Deviation (docs/algorithm/nosteiner2d.md "Delta and the shrink to
        // R"): the ray makes at least the angle atan(1/1.8) ~ 29 deg with its
        // side (the thesis's pi/4 from the bisector gives t/2 - pi/4, down to
        // pi/8 = 22.5 deg).
        const double beta = std::max(t / 2 - std::numbers::pi / 4, kMinRayAngle);
        const double lb = std::hypot(b.x, b.y);
        const Vec2 ub{b.x / lb, b.y / lb};
        const Vec2 u_out = rotate(ub, beta), u_in = rotate(ub, t - beta);  // beta from each side
        const double s = std::sin(beta);
        const double d_in = r.delta.side[l][kp] / 4, d_out = r.delta.side[l][k] / 4;
        const Vec2 w_in{v.x + u_in.x * d_in / s, v.y + u_in.y * d_in / s};
        const Vec2 w_out{v.x + u_out.x * d_out / s, v.y + u_out.y * d_out / s};
        out.push_back(w_in);
        vsrc.push_back(int(k));
        ssrc.push_back(-1 - int(k));
        sdel.push_back(r.delta.vertex[l][k]);
        out.push_back(w_out);
        vsrc.push_back(int(k));
        ssrc.push_back(int(k));
        sdel.push_back(r.delta.side[l][k]);
        if (r.valid && orient2d(v, w_out, w_in) != Sign::Positive) {
          r.valid = false;
          why << "loop " << l << ": the Case 2 side at Q vertex " << k << " does not turn around it";
        }
      }
    }
    // Each shrunk side keeps the direction of its Q side (exact).
    const std::size_t m = out.size();
    for (std::size_t j = 0; j < m && r.valid; ++j) {
      if (ssrc[j] < 0) continue;
      const std::size_t k = std::size_t(ssrc[j]);
      if (detail::dot_sign_directions(out[j], out[(j + 1) % m], lp[k], lp[(k + 1) % n]) != Sign::Positive) {
        r.valid = false;
        why << "loop " << l << ": the shrunk side of Q side " << k << " is reversed or empty";
      }
    }
  }
  r.failure = why.str();
  return r;
}

Domain2 polygon_r_domain(const PolygonR& r) {
  Pslg2 p;
  for (const auto& loop : r.loops) {
    const int base = int(p.vertices.size());
    const int m = int(loop.size());
    for (int j = 0; j < m; ++j) {
      p.vertices.push_back(loop[std::size_t(j)]);
      p.segments.push_back({base + j, base + (j + 1) % m});
    }
  }
  return make_domain(std::move(p));
}

}  // namespace pqmesh
