#include "plc/intersect_triangles.hpp"

#include "plc/facet_geometry.hpp"
#include "plc/polygon2d.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

bool mixed(Sign a, Sign b, Sign c) {
  const bool pos = a == Sign::Positive || b == Sign::Positive || c == Sign::Positive;
  const bool neg = a == Sign::Negative || b == Sign::Negative || c == Sign::Negative;
  return pos && neg;
}

// All three points strictly on one side of the plane of t.
bool strictly_one_side(const Tri3& t, Vec3 p, Vec3 q, Vec3 r) {
  const Sign a = orient3d(t[0], t[1], t[2], p);
  if (a == Sign::Zero) return false;
  return orient3d(t[0], t[1], t[2], q) == a && orient3d(t[0], t[1], t[2], r) == a;
}

// Segment v -> a, with v a vertex of triangle (v, c, d), meets the triangle at
// a point other than v. Off the plane it meets the plane only at v; in the
// plane (the triangle being convex and containing v) iff the direction a - v
// lies in the closed cone spanned by c - v and d - v.
bool edge_from_vertex_enters(Vec3 v, Vec3 a, Vec3 c, Vec3 d, int drop) {
  if (orient3d(v, c, d, a) != Sign::Zero) return false;
  const Vec2 V = project(v, drop), A = project(a, drop), C = project(c, drop), D = project(d, drop);
  const Sign s = orient2d(V, C, D);
  return orient2d(V, C, A) * s != Sign::Negative && orient2d(V, A, D) * s != Sign::Negative;
}

}  // namespace

bool segment_meets_triangle(Vec3 p, Vec3 q, const Tri3& t, int drop) {
  const Sign op = orient3d(t[0], t[1], t[2], p), oq = orient3d(t[0], t[1], t[2], q);
  if (op != Sign::Zero && op == oq) return false;
  if (op == Sign::Zero && oq == Sign::Zero) {
    const Vec2 P = project(p, drop), Q = project(q, drop);
    const Vec2 A = project(t[0], drop), B = project(t[1], drop), C = project(t[2], drop);
    return in_closed_triangle(P, A, B, C) || in_closed_triangle(Q, A, B, C) || segments_intersect(P, Q, A, B) ||
           segments_intersect(P, Q, B, C) || segments_intersect(P, Q, C, A);
  }
  // The line pq is not parallel to the plane and crosses it at one point of the
  // closed segment; that point is in the closed triangle iff the line passes
  // on no strictly different sides of the three edge lines.
  return !mixed(orient3d(p, q, t[0], t[1]), orient3d(p, q, t[1], t[2]), orient3d(p, q, t[2], t[0]));
}

// If the triangles meet, their intersection (a segment or convex polygon) has
// a point on an edge of one of them, so six segment tests decide.
bool triangles_meet(const Tri3& t, int drop_t, const Tri3& u, int drop_u) {
  if (strictly_one_side(t, u[0], u[1], u[2]) || strictly_one_side(u, t[0], t[1], t[2])) return false;
  for (int k = 0; k < 3; ++k) {
    if (segment_meets_triangle(t[k], t[(k + 1) % 3], u, drop_u)) return true;
    if (segment_meets_triangle(u[k], u[(k + 1) % 3], t, drop_t)) return true;
  }
  return false;
}

// The intersection is convex and contains v; if it has another point it has
// one (other than v) on an edge of one triangle lying in the other: an edge
// through v entering the other triangle, or the edge opposite v meeting it.
bool triangles_meet_beyond_vertex(Vec3 v, Vec3 a, Vec3 b, int drop_t, Vec3 c, Vec3 d, int drop_u) {
  const Tri3 t{v, a, b}, u{v, c, d};
  if (strictly_one_side(t, c, d, d) || strictly_one_side(u, a, b, b)) return false;  // touch at v only
  return edge_from_vertex_enters(v, a, c, d, drop_u) || edge_from_vertex_enters(v, b, c, d, drop_u) ||
         edge_from_vertex_enters(v, c, a, b, drop_t) || edge_from_vertex_enters(v, d, a, b, drop_t) ||
         segment_meets_triangle(a, b, u, drop_u) || segment_meets_triangle(c, d, t, drop_t);
}

bool triangles_overlap_beyond_edge(Vec3 u, Vec3 w, Vec3 c, Vec3 d, int drop) {
  if (orient3d(u, w, c, d) != Sign::Zero) return false;  // the planes meet only in the line uw
  const Vec2 U = project(u, drop), W = project(w, drop);
  return orient2d(U, W, project(c, drop)) == orient2d(U, W, project(d, drop));
}

}  // namespace pqmesh::detail
