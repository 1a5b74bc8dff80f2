// Phase 2 of constrained_delaunay(): constraint insertion by edge flips.
//
// For a constraint a -> b: if a - b is already an edge it is only marked (the
// fast path: consecutive points of a chain are usually Delaunay neighbours).
// Otherwise the walk from a along the segment collects the edges it crosses;
// it stops early at an input point exactly on the open segment, which splits
// the constraint there (the rest is inserted from that point on). The crossed
// edges of one piece A -> B are removed by Sloan's flips: take a crossed edge;
// if its two triangles form a strictly convex quadrilateral, flip it, and keep
// the new edge in the queue if it still crosses A-B, else remember it for the
// Delaunay check; a non-convex one goes to the back of the queue. (Some edge
// of the queue is always flippable, so this terminates; no vertex lies on the
// open segment A-B, so every edge of the region either crosses it or not.)
// Finally Lawson flips of non-constraint edges with a strict incircle test
// restore the constrained Delaunay property.
// (S. W. Sloan, "A fast algorithm for generating constrained Delaunay
// triangulations", Computers & Structures 47, 1993.)
#include <string>

#include "cdt2d/triangulation.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::cdt2d::detail {

void Triangulation::begin_constraints() {
  cons_.reserve(tris_.capacity());  // room for refinement (triangulation.hpp)
  cons_.assign(tris_.size(), 0);
  vtri_.reserve(pts_.capacity());
  vtri_.assign(pts_.size(), -1);
  for (int t = 0; t < triangle_count(); ++t) {
    if (is_ghost(t)) continue;
    for (int v : tris_[t].v) vtri_[v] = t;
  }
}

int Triangulation::index_in(int t, int v) const {
  const Tri& T = tris_[t];
  return T.v[0] == v ? 0 : (T.v[1] == v ? 1 : 2);
}

// Flip and keep vtri_ valid for the four vertices involved.
void Triangulation::flip_tracked(int h) {
  const int t = tri_of(h);
  const int u = tri_of(tris_[t].n[edge_of(h)]);
  flip(h);
  for (int v : tris_[t].v)
    if (v != kGhost) vtri_[v] = t;
  for (int v : tris_[u].v)
    if (v != kGhost) vtri_[v] = u;
}

// The half-edge u -> v (in the triangle on its left), or -1 when u - v is no
// edge. Rotates counter-clockwise around the real vertex u: in t = (u, w1, w2)
// the edge w2 -> u (edge index i + 1) leads to the next triangle around u.
int Triangulation::find_half_edge(int u, int v) const {
  const int t0 = vtri_[u];
  int t = t0;
  do {
    const int i = index_in(t, u);
    if (tris_[t].v[next3(i)] == v) return he(t, prev3(i));
    t = tri_of(tris_[t].n[next3(i)]);
  } while (t != t0);
  return -1;
}

void Triangulation::set_constrained(int h) {
  const int k = tris_[tri_of(h)].n[edge_of(h)];
  cons_[tri_of(h)] = static_cast<std::uint8_t>(cons_[tri_of(h)] | (1u << (edge_of(h))));
  cons_[tri_of(k)] = static_cast<std::uint8_t>(cons_[tri_of(k)] | (1u << (edge_of(k))));
}

namespace {

[[noreturn]] void throw_crossing(int a, int b, int u, int v) {
  throw InternalError("constrained_delaunay: constraint " + std::to_string(a) + "->" + std::to_string(b) +
                      " crosses constrained edge " + std::to_string(u) + "-" + std::to_string(v));
}

}  // namespace

void Triangulation::insert_constraint(int a, int b) {
  if (cons_.empty()) begin_constraints();
  const int a0 = a;
  const Vec2 B = pts_[b];
  while (a != b) {
    // Fast path: a - b is already an edge.
    if (const int h = find_half_edge(a, b); h >= 0) {
      set_constrained(h);
      pieces_.push_back({a, b});
      return;
    }
    // Find the triangle (a, u, w) around a whose wedge contains the direction
    // a -> b, or a neighbour of a exactly on the open segment a-b.
    const Vec2 A = pts_[a];
    const int t0 = vtri_[a];
    int t = t0, next_vertex = -1, start = -1;
    do {
      const int i = index_in(t, a);
      const Tri& T = tris_[t];
      const int u = T.v[next3(i)], w = T.v[prev3(i)];
      if (u != kGhost && w != kGhost) {
        const Sign su = orient2d(A, B, pts_[u]);
        const Sign sw = orient2d(A, B, pts_[w]);
        // A neighbour on the ray from a towards b is strictly between a and
        // b: b itself is no neighbour, and b cannot lie inside edge a-u.
        if (su == Sign::Zero && dot_sign(A, pts_[u], B) == Sign::Positive) {
          next_vertex = u;
          break;
        }
        if (sw == Sign::Zero && dot_sign(A, pts_[w], B) == Sign::Positive) {
          next_vertex = w;
          break;
        }
        if (su == Sign::Negative && sw == Sign::Positive) {
          start = he(t, i);  // edge u -> w, u right of a -> b, w left
          break;
        }
      }
      t = tri_of(T.n[next3(i)]);
    } while (t != t0);

    if (next_vertex >= 0) {
      set_constrained(find_half_edge(a, next_vertex));
      pieces_.push_back({a, next_vertex});
      a = next_vertex;
      continue;
    }
    if (start < 0)
      throw InternalError("constrained_delaunay: no triangle around " + std::to_string(a) + " in direction of " +
                          std::to_string(b));

    // Walk along a -> b collecting crossed edges as (right, left) vertex pairs.
    crossed_.clear();
    int h = start;
    int r = tris_[tri_of(h)].v[next3(edge_of(h))], l = tris_[tri_of(h)].v[prev3(edge_of(h))];
    int end = -1;
    for (;;) {
      if (constrained(h)) throw_crossing(a0, b, r, l);
      crossed_.push_back({r, l});
      const int k = tris_[tri_of(h)].n[edge_of(h)];
      const int s = tri_of(k), j = edge_of(k);  // tris_[s] = (x, l, r) from index j
      const int x = tris_[s].v[j];
      if (x == kGhost) throw InternalError("constrained_delaunay: constraint walk left the convex hull");
      if (x == b) {
        end = b;
        break;
      }
      const Sign o = orient2d(A, B, pts_[x]);
      if (o == Sign::Zero) {  // x on the open segment (the walk must leave s through x)
        end = x;
        break;
      }
      if (o == Sign::Positive) {
        h = he(s, next3(j));  // edge r -> x, opposite l
        l = x;
      } else {
        h = he(s, prev3(j));  // edge x -> l, opposite r
        r = x;
      }
    }
    sloan_flips(a, end);
    const int he = find_half_edge(a, end);
    if (he < 0) throw InternalError("constrained_delaunay: constraint edge not recovered by flips");
    set_constrained(he);
    pieces_.push_back({a, end});
    restore_delaunay();
    a = end;
  }
}

// Remove the edges of crossed_ (all crossing the open segment a-b, no vertex
// on it) by flips; fills fresh_ with the new edges that do not cross.
void Triangulation::sloan_flips(int a, int b) {
  const Vec2 A = pts_[a], B = pts_[b];
  fresh_.clear();
  std::size_t head = 0;
  const std::size_t k = crossed_.size();
  const std::size_t cap = 64 + 16 * (k + 1) * (k + 1);
  for (std::size_t steps = 0; head < crossed_.size(); ++steps) {
    if (steps > cap) throw InternalError("constrained_delaunay: segment recovery by flips does not terminate");
    const auto [u, v] = crossed_[head++];
    const int h = find_half_edge(u, v);
    if (h < 0) throw InternalError("constrained_delaunay: lost a crossed edge");
    const int t = tri_of(h), i = edge_of(h);
    const int n = tris_[t].n[i];
    const int c = tris_[t].v[i], d = tris_[tri_of(n)].v[edge_of(n)];
    const Vec2 C = pts_[c], D = pts_[d];
    if (orient2d(C, D, pts_[u]) * orient2d(C, D, pts_[v]) != Sign::Negative) {
      crossed_.push_back({u, v});  // not strictly convex yet
      continue;
    }
    flip_tracked(h);
    if (orient2d(A, B, C) * orient2d(A, B, D) == Sign::Negative)
      crossed_.push_back({c, d});
    else
      fresh_.push_back({c, d});
  }
}

// Lawson flips over fresh_ and the edges around every flip, skipping
// constrained and hull edges; strict incircle, so ties never flip.
void Triangulation::restore_delaunay() {
  while (!fresh_.empty()) {
    const auto [u, v] = fresh_.back();
    fresh_.pop_back();
    if (u == kGhost || v == kGhost) continue;
    const int h = find_half_edge(u, v);
    if (h < 0 || constrained(h)) continue;  // flipped away meanwhile, or a constraint
    const int t = tri_of(h), i = edge_of(h);
    const int n = tris_[t].n[i];
    const int c = tris_[t].v[i], d = tris_[tri_of(n)].v[edge_of(n)];
    if (c == kGhost || d == kGhost) continue;
    if (incircle(pts_[c], pts_[u], pts_[v], pts_[d]) != Sign::Positive) continue;
    flip_tracked(h);
    fresh_.push_back({c, u});
    fresh_.push_back({u, d});
    fresh_.push_back({d, v});
    fresh_.push_back({v, c});
  }
}

}  // namespace pqmesh::cdt2d::detail
