#pragma once
// alpha: the smallest interior angle between two faces of the input domain
// (thesis ch. 3, "Interior angle"; used as alpha throughout ch. 4), together
// with the pair of faces that realises it.
//
// Thesis definition (ch. 3). Two faces f, g meeting at a vertex v (neither a
// subset of the other) make the angle between rays from v that "see each
// other": rays r1, r2 see each other when, for some t > 0, the planar sector
// v v1 v2 (v_i on r_i at distance t) lies in P. Angles are measured through
// the interior of P, so they lie in (0, 2*pi).
//   edge-edge    the angle between the two edge rays;
//   edge-facet   the minimum over rays r of the facet's plane lying between the
//                facet's two edges at v (inside the facet) and seeing the edge;
//   facet-facet  at a common vertex: both rays vary; at a common edge: the
//                dihedral angle (rays perpendicular to the edge).
// The thesis notes that alpha is always realised by two edges or by an edge
// and a facet; src/plc/alpha3.cpp explains which candidates are evaluated and
// why that suffices, and which decisions are exact.
#include <string>
#include <vector>

#include "pqmesh/plc.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

struct FaceRef {
  enum class Kind { None, Vertex, Edge, Facet };
  Kind kind = Kind::None;
  int id = -1;         // Vertex: vertex id; Facet: facet id; Edge: -1 (see a, b)
  int a = -1, b = -1;  // Edge: its two vertex ids, a < b
  static FaceRef vertex(int v) { return {Kind::Vertex, v, -1, -1}; }
  static FaceRef edge(int p, int q) { return {Kind::Edge, -1, p < q ? p : q, p < q ? q : p}; }
  static FaceRef facet(int f) { return {Kind::Facet, f, -1, -1}; }
  // "vertex 3", "edge 1-4", "facet 7" in the file's numbering (id + first_id).
  std::string describe(int first_id) const;
};

struct AlphaResult {
  double radians = 0;
  int apex = -1;  // the vertex where the angle is measured (an endpoint of the edge for a dihedral)
  FaceRef first, second;
  // "edge-edge", "edge-facet", "facet-facet (dihedral)" (the 3D kinds), or
  // "edge-edge" for a 2D polygon corner.
  std::string kind;
  // Sanity data (3D only; equals radians in 2D): the smallest interior dihedral
  // angle over all edges. By the thesis' remark, radians <= min_dihedral_radians.
  double min_dihedral_radians = 0;
  double degrees() const;
  // e.g. "alpha = 54.7356 deg (edge-facet) at vertex 0: edge 0-1 and facet 2",
  // ids in the file's numbering (id + first_id).
  std::string describe(int first_id) const;
};

// 3D. PRECONDITION: a valid closed domain (thesis §1.4: every edge on exactly
// two facets) whose facets are oriented outward: each Facet3's loops[0] turns
// counter-clockwise seen from outside P (its right-hand normal points out of
// P) and hole loops turn the other way. Throws DomainError for an edge that is
// not on exactly two facets or is traversed the same way by both, and
// EmptyDomain when there are no facets.
// Cost: O(sum over vertices of deg(v)^2 * (deg(v) + corners(v))) in the worst
// case; the visibility test runs only for candidates that would improve the
// current minimum.
AlphaResult compute_alpha(const Plc3& oriented);

// 2D polygon with holes; every loop lists vertex ids with the interior of the
// domain on its LEFT (outer loop counter-clockwise, holes clockwise). Reports
// the smallest interior corner angle (corners may be reflex, up to 2*pi), its
// vertex (apex) and its two sides (first, second as edges).
AlphaResult compute_alpha(const std::vector<Vec2>& vertices, const std::vector<std::vector<int>>& loops);

}  // namespace pqmesh
