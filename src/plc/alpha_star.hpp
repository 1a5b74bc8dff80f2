#pragma once
// Internal to the alpha computation (include/pqmesh/alpha.hpp): the local
// structure of an outward-oriented Plc3 around its vertices and the exact
// side/visibility tests the candidate enumeration in alpha3.cpp needs.
//
// Vocabulary.
//   corner   one occurrence of a vertex v in a facet loop, with the loop's
//            previous vertex a and next vertex b. Loops turn counter-clockwise
//            around the outward normal with the facet on their left, so the
//            facet's sector at v runs counter-clockwise (about the outward
//            normal) from ray v->b to ray v->a.
//   cone K   the solid cone of P at v (the limit of (P - v) scaled up); its
//            boundary is the union of the corners' sectors.
//   link     K's boundary intersected with the unit sphere around v: a closed
//            curve of great-circle arcs, one per corner, meeting at the edge
//            directions (thesis §1.4 makes it one curve).
#include <array>
#include <vector>

#include "pqmesh/plc.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

// Exact orientation data of one facet's plane.
struct FacetFrame {
  std::array<int, 3> triple{};  // three facet vertices whose right-hand normal points out of P
  int drop = 2;                 // coordinate axis dropped for in-plane 2D predicates
  Sign drop_sign = Sign::Positive;  // exact sign of the outward normal's drop component
  Vec3 unit_normal;             // outward unit normal (construction: Newell sum)
};

// One side of an edge: the facet and the position in its loop where the
// directed loop edge loops[loop][pos] -> loops[loop][pos + 1] runs along it.
struct EdgeSide {
  int facet = -1, loop = -1, pos = -1;
};

enum class EdgeShape { Convex, Flat, Reflex };  // interior dihedral <, =, > pi

struct EdgeInfo {
  int a = -1, b = -1;  // a < b
  std::array<EdgeSide, 2> sides;
  EdgeShape shape = EdgeShape::Flat;
  double dihedral = 0;  // interior dihedral angle in (0, 2*pi), a construction
};

struct Corner {
  int facet = -1;
  int prev = -1, next = -1;  // loop neighbours a, b of the vertex
};

class AlphaGeometry {
 public:
  // Throws DomainError (OpenBoundary, NonManifoldEdge, DegenerateFacet) when
  // the precondition of compute_alpha is visibly violated.
  explicit AlphaGeometry(const Plc3& plc);

  const Plc3& plc() const { return plc_; }
  const std::vector<FacetFrame>& frames() const { return frames_; }
  const std::vector<EdgeInfo>& edges() const { return edges_; }
  int vertex_count() const { return int(plc_.vertices.size()); }
  // Corners and neighbour vertices (edges) of v, both in a deterministic order.
  const std::vector<Corner>& corners(int v) const { return corners_[v]; }
  const std::vector<int>& neighbours(int v) const { return neighbours_[v]; }
  // Index into edges() of edge {p, q}, -1 if it is not an edge.
  int find_edge(int p, int q) const;

  // Exact: Positive when point x is strictly on the outer side of facet f's
  // plane, Negative on the inner side, Zero on the plane.
  Sign side(int f, Vec3 x) const;
  // Exact for points in facet f's plane (and exact on the given doubles
  // otherwise): Positive when r lies left of the directed line p->q, seen from
  // outside P.
  Sign left_in_facet(int f, Vec3 p, Vec3 q, Vec3 r) const;
  // Exact turn of a corner: Positive convex (sector angle < pi), Zero
  // straight, Negative reflex.
  Sign corner_turn(int v, const Corner& c) const;
  // Sector membership of point x (a direction x - v) in corner c at v:
  // closed (boundary rays included) or open.
  bool in_closed_sector(int v, const Corner& c, Vec3 x) const;
  bool in_open_sector(int v, const Corner& c, Vec3 x) const;

  // Do the rays v->x (x a neighbour vertex: an edge of P) and v->w (w a point;
  // an input vertex or a construction) see each other through the convex
  // planar sector between them (thesis ch. 3)? w_vertex is w's vertex id when
  // w is an input vertex, else -1. skip_facet >= 0 names a facet whose plane
  // contains w by construction (w is a projection into it); its sides are then
  // not used. See alpha_star.cpp for the method.
  bool sees(int v, int x, Vec3 w, int w_vertex, int skip_facet) const;

 private:
  const Plc3& plc_;
  std::vector<FacetFrame> frames_;
  std::vector<EdgeInfo> edges_;
  std::vector<std::vector<Corner>> corners_;
  std::vector<std::vector<int>> neighbours_;

  void build_frames();
  void build_edges();
  void classify_edges();
  // A point of facet side s's plane strictly inside the half-plane the facet
  // occupies next to its edge, as (point, +1), or strictly in the opposite
  // half-plane, as (point, -1).
  std::pair<Vec3, int> halfplane_witness(const EdgeSide& s) const;
  bool interior_from_edge(const EdgeInfo& e, Vec3 w) const;
};

}  // namespace pqmesh::detail
