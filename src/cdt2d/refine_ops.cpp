// Phase 4 of the triangulation (refine.hpp): point insertion into a finished
// constrained Delaunay triangulation, keeping the inside labels, the
// constraint bits and the vertex -> triangle map.
//
// Invariants kept by both operations:
//   - inside_ has one label per triangle slot; a triangle made from an inside
//     triangle is inside, from an outside (or ghost) one outside;
//   - inside triangles are strictly counter-clockwise and tile the current
//     domain (which moves by less than the rounding when boundary edges are
//     split, see split_constrained_edge);
//   - a "trusted" outside triangle is strictly counter-clockwise and its
//     region is disjoint from every inside triangle and from every other
//     trusted triangle (true for all outside triangles of the initial CDT).
//     Outside triangles that may be flat or inverted are "untrusted"; no
//     geometric decision ever relies on them.
//   - flips happen only across non-constrained edges between two inside
//     triangles, so the inside region (bounded by constrained edges) is
//     unchanged as a set and labels never need recomputing;
//   - every non-constrained edge between inside triangles is locally
//     Delaunay afterwards (strict incircle, ties never flip), as before.
#include <utility>

#include "cdt2d/triangulation.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::cdt2d::detail {

void Triangulation::begin_refinement(std::vector<std::uint8_t> inside) {
  if (cons_.empty()) begin_constraints();
  inside_ = std::move(inside);
  if (inside_.size() != tris_.size()) throw InternalError("refine: inside labels do not match the triangles");
}

void Triangulation::set_vertex_triangle(int p, int t) {
  if (static_cast<std::size_t>(p) >= vtri_.size()) vtri_.resize(static_cast<std::size_t>(p) + 1, -1);
  vtri_[p] = t;
}

// split_triangle puts the new point at index 0 of the three triangles and the
// old edge i of t at edge 0 of the i-th new triangle (t, then two appended).
void Triangulation::insert_interior_point(int p, int t, int edge) {
  if (edge < 0) {
    const Tri T = tris_[t];
    const std::uint8_t c = cons_[t], in = inside_[t];
    split_triangle(t, p);
    const int t1 = triangle_count() - 2;
    cons_[t] = static_cast<std::uint8_t>(c & 1u);
    cons_.push_back(static_cast<std::uint8_t>((c >> 1) & 1u));
    cons_.push_back(static_cast<std::uint8_t>((c >> 2) & 1u));
    inside_.push_back(in);
    inside_.push_back(in);
    set_vertex_triangle(p, t);
    vtri_[T.v[0]] = t1;  // (p, c, a) holds a = T.v[0]
    vtri_[T.v[1]] = t;
    vtri_[T.v[2]] = t;
  } else {
    const int h = he(t, edge);
    if (constrained(h)) throw InternalError("refine: interior point on a constrained edge");
    const int i = edge, k = tris_[t].n[i];
    const int u = tri_of(k), j = edge_of(k);
    const Tri T = tris_[t], U = tris_[u];
    auto bit = [&](int tri, int e) { return static_cast<std::uint8_t>((cons_[tri] >> e) & 1u); };
    const std::uint8_t c_bc = bit(t, next3(i)), c_ca = bit(t, prev3(i)), c_ad = bit(u, next3(j)),
                       c_db = bit(u, prev3(j));
    split_edge(h, p);
    const int t2 = triangle_count() - 2;
    cons_[t] = c_bc;
    cons_[u] = c_ca;
    cons_.push_back(c_ad);
    cons_.push_back(c_db);
    inside_.push_back(inside_[u]);
    inside_.push_back(inside_[u]);
    set_vertex_triangle(p, t);
    vtri_[T.v[i]] = t;          // c
    vtri_[T.v[next3(i)]] = u;   // a in (p, c, a)
    vtri_[T.v[prev3(i)]] = t;   // b
    if (U.v[j] != kGhost) vtri_[U.v[j]] = t2;  // d in (p, a, d)
  }
  legalize_constrained(p);
}

// h = a -> b in the inside triangle (c, a, b), neighbour (d, b, a). After the
// split the fan around p is (p, b, c), (p, c, a), (p, a, d), (p, d, b).
// (p, b, c) and (p, c, a) must always be strictly counter-clockwise.
//   - Neighbour inside (an interior constraint), or p strictly right of
//     a -> b: all four must be strictly counter-clockwise, and for p right of
//     a -> b the neighbour must be a trusted outside triangle. The angles at
//     p then add up to 2 pi times the winding number of the simple polygon
//     c, a, d, b around p, so p is inside it and the fan tiles it exactly
//     once: the domain grows by the sliver (a, b, p), which lies in the
//     trusted triangle (d, b, a), disjoint from all inside triangles; the two
//     new outside triangles tile the rest of it and stay trusted.
//   - Outside (or ghost) neighbour and p not strictly right of a -> b: the
//     two inside triangles tile the old triangle minus the sliver (a, p, b),
//     so the domain only shrinks, by less than the rounding. The outside
//     triangles are not needed to be valid (the boundary points of one side
//     are nearly collinear, so the outside triangles between them are
//     slivers that a rounded point easily inverts): they stay trusted only
//     when the old one was and both new ones are strictly counter-clockwise
//     (then they tile the old one plus the sliver, which left the domain).
bool Triangulation::split_constrained_edge(int h, int p) {
  const int t = tri_of(h), i = edge_of(h);
  const int k = tris_[t].n[i];
  const int u = tri_of(k), j = edge_of(k);
  const Tri T = tris_[t], U = tris_[u];
  const int c = T.v[i], a = T.v[next3(i)], b = T.v[prev3(i)], d = U.v[j];
  if (c == kGhost || a == kGhost || b == kGhost || inside_[t] != kLabelInside)
    throw InternalError("refine: constrained edge split from an outside triangle");
  const Vec2 P = pts_[p];
  if (orient2d(P, pts_[b], pts_[c]) != Sign::Positive || orient2d(P, pts_[c], pts_[a]) != Sign::Positive) return false;
  const bool far_ok = d != kGhost && orient2d(P, pts_[a], pts_[d]) == Sign::Positive &&
                      orient2d(P, pts_[d], pts_[b]) == Sign::Positive;
  const bool right = orient2d(pts_[a], pts_[b], P) == Sign::Negative;
  std::uint8_t far_label = inside_[u];
  if (inside_[u] == kLabelInside) {
    if (!far_ok) return false;
  } else if (right) {
    if (!far_ok || inside_[u] != kLabelTrusted || d == kGhost) return false;
  } else if (!far_ok || d == kGhost) {
    far_label = kLabelUntrusted;
  }
  auto bit = [&](int tri, int e) { return static_cast<std::uint8_t>((cons_[tri] >> e) & 1u); };
  const std::uint8_t c_bc = bit(t, next3(i)), c_ca = bit(t, prev3(i)), c_ad = bit(u, next3(j)), c_db = bit(u, prev3(j));
  const std::uint8_t in_t = inside_[t], in_u = far_label;
  split_edge(h, p);
  const int t2 = triangle_count() - 2;
  // Edge p-b is edge 2 of (p, b, c) and edge 1 of (p, d, b); edge a-p is edge
  // 1 of (p, c, a) and edge 2 of (p, a, d).
  cons_[t] = static_cast<std::uint8_t>(c_bc | (1u << 2));
  cons_[u] = static_cast<std::uint8_t>(c_ca | (1u << 1));
  cons_.push_back(static_cast<std::uint8_t>(c_ad | (1u << 2)));
  cons_.push_back(static_cast<std::uint8_t>(c_db | (1u << 1)));
  inside_[t] = in_t;
  inside_[u] = in_t;
  inside_.push_back(in_u);
  inside_.push_back(in_u);
  set_vertex_triangle(p, t);
  vtri_[c] = t;
  vtri_[a] = u;
  vtri_[b] = t;
  if (d != kGhost) vtri_[d] = t2;
  legalize_constrained(p);
  return true;
}

// Lawson flips around the new point p (stack_ holds triangles with p at index
// 0, see legalize()): an edge opposite p is flipped when it is not
// constrained, its triangle is inside and the opposite vertex is strictly in
// the circumcircle. Outside triangles (the far side of a split boundary edge)
// are left as they are: they are discarded and need no Delaunay property.
void Triangulation::legalize_constrained(int p) {
  const Vec2 q = pts_[p];
  while (!stack_.empty()) {
    const int t = stack_.back();
    stack_.pop_back();
    if (inside_[t] != kLabelInside || constrained(he(t, 0))) continue;
    const Tri& T = tris_[t];
    const int h = T.n[0];
    const int s = tri_of(h);
    const int d = tris_[s].v[edge_of(h)];
    if (d == kGhost || inside_[s] != kLabelInside) continue;
    if (incircle(q, pts_[T.v[1]], pts_[T.v[2]], pts_[d]) != Sign::Positive) continue;
    flip_tracked(he(t, 0));
    stack_.push_back(t);
    stack_.push_back(s);
  }
}

}  // namespace pqmesh::cdt2d::detail
