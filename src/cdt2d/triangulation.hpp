#pragma once
// The triangulation data structure behind constrained_delaunay() (internal).
//
// Storage: one flat array of small triangles, no per-triangle allocation.
// Triangle t has vertices v[0], v[1], v[2] in counter-clockwise order. Its
// edge i is the edge opposite v[i], directed from v[i+1] to v[i+2] (indices
// mod 3); half-edge h = 4 t + i names it (he(t, i)), and n[i] is the half-edge of the
// neighbouring triangle across it (the same edge, directed the other way).
//
// Ghost vertex: kGhost (-1) closes the surface. Every convex hull edge u -> v
// (interior on its right, seen as an edge of the ghost triangle) carries a
// ghost triangle (u, v, kGhost), so the triangles form a triangulated sphere
// and every half-edge has a neighbour. Invariants between operations:
//   - real triangles (no ghost vertex) have orient2d > 0 and tile the convex
//     hull of the inserted points; hull vertices that are collinear with their
//     hull neighbours stay hull vertices (no zero-area triangle is made);
//   - n[] is an involution on half-edges: n(n(h)) == h;
//   - in the Delaunay phase every edge is locally Delaunay with the ghost
//     rule below; after constraint insertion every non-constraint edge is.
//
// Ghost rule (the "circumcircle" of a ghost triangle (u, v, g) is the open
// half plane left of u -> v): a point p is strictly inside it iff
// orient2d(u, v, p) > 0. Points exactly on the hull line are never inside, so
// flips never create zero-area triangles.
//
// Triangle slots are never freed: a 1-3 split adds two, a 2-4 split adds two,
// a flip reuses its two slots. With n points and the ghost the sphere has
// 2 (n + 1) - 4 triangles at the end. The per-triangle and per-vertex arrays
// are reserved up front for the point array's capacity, not its size: a
// refinement gives its points room to grow (refine.cpp), and its few new
// points then never reallocate (copy, and touch anew) the large arrays.
#include <array>
#include <cstdint>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh::cdt2d::detail {

inline constexpr int kGhost = -1;

constexpr int next3(int i) { return i == 2 ? 0 : i + 1; }
constexpr int prev3(int i) { return i == 0 ? 2 : i - 1; }
// Half-edge h = 4 t + i (edge i of triangle t; shifts instead of divisions).
constexpr int he(int t, int i) { return (t << 2) | i; }
constexpr int tri_of(int h) { return h >> 2; }
constexpr int edge_of(int h) { return h & 3; }

struct Tri {
  int v[3];
  int n[3];
};

class Triangulation {
 public:
  explicit Triangulation(const std::vector<Vec2>& points);

  // Phase 1: Delaunay triangulation of all points, inserted in input order
  // (triangulation.cpp). Returns false when there are fewer than three points
  // or all points are collinear (then there is no triangle). Throws
  // InternalError on duplicate points.
  bool build_delaunay();

  // Phase 2 (constraints.cpp): make a -> b a chain of constrained edges and
  // restore the constrained Delaunay property. Records the directed pieces.
  void insert_constraint(int a, int b);

  // Phase 3 (flood_fill.cpp): per triangle, 1 when on the inside (flood fill
  // from the left of every constraint piece), else 0.
  std::vector<std::uint8_t> inside_triangles() const;

  // Phase 4 (refine_ops.cpp): support for Delaunay refinement (refine.hpp).
  // The point array given to the constructor may grow between calls (the
  // triangulation keeps a reference to the vector, not to its storage).
  // begin_refinement takes the inside labels of inside_triangles(); from then
  // on every operation keeps them, the constraint bits and vtri_ up to date.
  void begin_refinement(std::vector<std::uint8_t> inside);
  bool inside(int t) const { return inside_[static_cast<std::size_t>(t)] == kLabelInside; }
  // A real outside triangle whose region is known to be disjoint from the
  // inside triangles (see split_constrained_edge).
  bool trusted_outside(int t) const { return !is_ghost(t) && inside_[static_cast<std::size_t>(t)] == kLabelTrusted; }
  int vertex_triangle(int v) const { return vtri_[static_cast<std::size_t>(v)]; }
  int index_of(int t, int v) const { return index_in(t, v); }
  int half_edge(int u, int v) const { return find_half_edge(u, v); }
  const std::vector<std::array<int, 2>>& pieces() const { return pieces_; }
  // Frees the constraint bits and the vertex -> triangle map (their memory)
  // once only the triangles and their inside labels are still read: after
  // it, constrained() is false everywhere and no operation may be called.
  void release_refinement_maps() {
    cons_ = {};
    vtri_ = {};
  }
  // Point p strictly inside the inside triangle t (edge < 0), or in the
  // relative interior of the non-constrained edge `edge` of t (both sides
  // inside, as a walk that never crosses a constraint finds it): 1-3 or 2-4
  // split, then Lawson flips that never cross a constrained edge.
  void insert_interior_point(int p, int t, int edge);
  // Split the constrained edge of half-edge h (its triangle inside) at the new
  // point p, which the caller constructed near the edge (a rounded point, not
  // necessarily exactly on it). The two halves stay constrained. Nothing
  // changes and false is returned when one of the new real triangles would
  // not be strictly counter-clockwise (exact orient2d): then the four new
  // triangles tile the old quadrilateral exactly (see refine_ops.cpp).
  bool split_constrained_edge(int h, int p);

  int triangle_count() const { return static_cast<int>(tris_.size()); }
  const Tri& tri(int t) const { return tris_[t]; }
  bool is_ghost(int t) const { return tris_[t].v[0] < 0 || tris_[t].v[1] < 0 || tris_[t].v[2] < 0; }
  bool constrained(int h) const { return !cons_.empty() && ((cons_[tri_of(h)] >> (edge_of(h))) & 1u) != 0; }
  bool any_constrained(int t) const { return !cons_.empty() && cons_[t] != 0; }

 private:
  struct Location {
    int t = -1;     // the triangle found
    int edge = -1;  // >= 0: the point lies in the relative interior of this edge of t
  };

  // triangulation.cpp
  void make_first_triangle(int a, int b, int c);
  Location locate(int p);
  void insert_point(int p);
  void split_triangle(int t, int p);
  void split_edge(int h, int p);
  void legalize(int p);
  int random3();

  // shared helpers
  void set_twin(int h, int k) { tris_[tri_of(h)].n[edge_of(h)] = k; }  // one direction of link()
  void link(int h, int k) {
    set_twin(h, k);
    set_twin(k, h);
  }
  void flip(int h);          // see triangulation.cpp
  void flip_at_apex(int t);  // flip(he(t, 0)) in phase 1

  // constraints.cpp
  void begin_constraints();
  void flip_tracked(int h);
  int find_half_edge(int u, int v) const;
  void set_constrained(int h);
  int index_in(int t, int v) const;
  void sloan_flips(int a, int b);
  void restore_delaunay();

  // refine_ops.cpp
  void legalize_constrained(int p);
  void set_vertex_triangle(int p, int t);

  const std::vector<Vec2>& pts_;
  std::vector<Tri> tris_;
  static constexpr std::uint8_t kLabelTrusted = 0, kLabelInside = 1, kLabelUntrusted = 2;
  std::vector<std::uint8_t> inside_;         // phase 4: kLabelInside, kLabelTrusted or kLabelUntrusted per triangle
  std::vector<std::uint8_t> cons_;           // bit i of cons_[t]: edge i of t is constrained (phase 2 only)
  std::vector<int> vtri_;                    // phase 2: a triangle incident to each vertex
  std::vector<std::array<int, 2>> pieces_;   // constrained pieces, directed as given
  std::vector<int> stack_;                   // phase 1: triangles around the new point to check
  std::vector<std::array<int, 2>> crossed_;  // phase 2 scratch: edges crossed by a piece
  std::vector<std::array<int, 2>> fresh_;    // phase 2 scratch: edges to re-check for Delaunay
  int last_ = 0;                             // a real triangle made by the latest insertion
  std::uint64_t rng_ = 0x9e3779b97f4a7c15ull;
};

}  // namespace pqmesh::cdt2d::detail
