// Delaunay refinement without constraint splits (refine.hpp "Without
// constraint splits"; RefineOptions::split_constraints = false): every new
// point strictly inside the domain, none on a constrained edge.
#include <cmath>

#include "cdt2d/refiner.hpp"

namespace pqmesh::cdt2d::detail {
namespace {

// The apexes of a constrained edge ab tried in turn: base angles 60, 45 and
// 32 degrees (tangents below), so |a apex| = |ab| / (2 cos beta); rule (b)
// for an apex compares with 0.99 (|a apex| / |ab|)^2 |ab|^2 (kApexNear).
constexpr double kApexTan[] = {1.7320508075688772, 1.0, 0.62486935190932746};
constexpr double kApexNear[] = {0.99, 0.495, 0.99 / (4 * 0.71918557339453874)};  // 0.99 / (4 cos^2 beta)

}  // namespace

// Some vertex of the cavity (cavity_, filled by collect_encroached) is
// strictly closer to c than sqrt(l2) (squared lengths in double). Cost:
// O(cavity).
bool Refiner::too_near_cavity(double l2, Vec2 c) const {
  for (const int k : cavity_)
    for (const int x : tri_.tri(k).v) {
      const Vec2 d = pts_[x] - c;
      if (dot(d, d) < l2) return true;
    }
  return false;
}

// Squared length of the shortest edge of t (double).
double Refiner::shortest2(int t) const {
  const auto& v = tri_.tri(t).v;
  const int m = shortest_edge(t);
  const Vec2 e = pts_[v[next3(m)]] - pts_[v[prev3(m)]];
  return dot(e, e);
}

// A constrained edge ab of the cavity (cavity_) other than the half-edge
// `except` that c encroaches (exact dot_sign: c sees ab under >= 90 degrees,
// so the circumcenter of the triangle abc that inserting c makes is on or
// beyond ab) and where that triangle has an angle below the target at a or
// b (law of cosines in double: a choice, not a validity decision): a bad
// triangle that refinement could never improve. Its half-edge (of the
// inside triangle), or -1. Cost: O(cavity).
int Refiner::flat_constrained_edge(Vec2 c, int except) const {
  auto sharp_at = [&](Vec2 a, Vec2 b) {  // the angle at a of triangle a b c is below the target
    const Vec2 ab = b - a, ac = c - a;
    return dot(ab, ac) > cos_target_ * std::sqrt(dot(ab, ab) * dot(ac, ac));
  };
  for (const int k : cavity_)
    for (int e = 0; e < 3; ++e) {
      const int h = he(k, e);
      if (h == except || !tri_.constrained(h)) continue;
      const Vec2 a = pts_[tri_.tri(k).v[next3(e)]], b = pts_[tri_.tri(k).v[prev3(e)]];
      if (dot_sign(c, a, b) != Sign::Positive && (sharp_at(a, b) || sharp_at(b, a))) return h;
    }
  return -1;
}

// An apex of the constrained half-edge h = a -> b (its triangle on the
// left): the point on the perpendicular bisector of ab, on the triangle's
// side, at height tan(beta) |ab| / 2, where the triangle a b apex has base
// angles beta.
Vec2 Refiner::apex_of(int h, double tan_beta) const {
  const auto& T = tri_.tri(tri_of(h));
  const Vec2 a = pts_[T.v[next3(edge_of(h))]], b = pts_[T.v[prev3(edge_of(h))]];
  const Vec2 d = b - a;
  return 0.5 * (a + b) + (0.5 * tan_beta) * Vec2{-d.y, d.x};
}

// The bad triangle q.t with new point c (off-center or circumcenter), walk w
// from q.t towards c. Inserted: c when (a) the walk reached it strictly
// inside the domain, (b) no cavity vertex is nearer to c than q.t's shortest
// edge and (c) no constrained edge of its cavity is "flat" for it
// (flat_constrained_edge). Otherwise, in this order, the first of these that
// passes (a), (b), (c) is inserted and q re-queued: the three apexes of the
// constrained edge that stopped the walk or is flat (rule (b) against the
// smaller of q.t's shortest edge and 0.99 |a apex|^2, rule (c) that edge
// excepted), then the point halfway between the midpoint of q.t's shortest
// edge and c. If none passes, q is given up. The fallback points are fixed
// points of their edge or of q.t: each is inserted at most once (a second
// walk ends on the vertex).
void Refiner::refine_inside(const QueuedTri& q, Vec2 c, const Walk& w) {
  int blocking = -1;
  if (w.end == Walk::End::Constraint) {
    blocking = w.h;
  } else if (w.end == Walk::End::Triangle || w.end == Walk::End::Edge) {
    collect_encroached(w, c);  // the cavity; encroachment itself is ignored
    if (too_near_cavity(shortest2(q.t), c)) {
      ++given_up_near_;
      return;
    }
    blocking = flat_constrained_edge(c, -1);
    if (blocking < 0) {
      insert_interior(c, w);
      return;
    }
  } else {  // on a vertex, or the walk failed
    ++given_up_outside_;
    return;
  }
  for (int k = 0; k < 3; ++k)
    if (try_point(q, tri_of(blocking), apex_of(blocking, kApexTan[k]),
                  std::min(shortest2(q.t), kApexNear[k] * length2_of(blocking)), blocking)) {
      ++apex_points_;
      return;
    }
  const auto& v = tri_.tri(q.t).v;
  const int m = shortest_edge(q.t);
  const Vec2 mid = 0.5 * (pts_[v[next3(m)]] + pts_[v[prev3(m)]]);
  if (try_point(q, q.t, mid + 0.5 * (c - mid), shortest2(q.t), -1)) ++halfway_points_;
}

// Inserts p for the bad triangle q when the walk from triangle `from`
// reaches p strictly inside the domain (rule (a)), no cavity vertex is
// nearer than sqrt(near2) (rule (b)) and no constrained cavity edge other
// than `except` is flat for p (rule (c)); q is then re-queued.
bool Refiner::try_point(const QueuedTri& q, int from, Vec2 p, double near2, int except) {
  const Walk wp = walk_to(from, p);
  if (wp.end != Walk::End::Triangle && wp.end != Walk::End::Edge) {
    ++given_up_outside_;
    return false;
  }
  collect_encroached(wp, p);
  if (too_near_cavity(near2, p)) {
    ++given_up_near_;
    return false;
  }
  if (flat_constrained_edge(p, except) >= 0) {
    ++given_up_flat_;
    return false;
  }
  insert_interior(p, wp);
  if (still_there(q)) requeue(q);
  return true;
}

}  // namespace pqmesh::cdt2d::detail
