#pragma once
// Validated input domains (docs/algorithm/input.md, thesis §1.4).
//
// make_domain() checks every assumption the meshers rely on and throws a
// DomainError naming the offending ids (in the file's numbering) and file line
// otherwise. On success the facets are oriented outward and the boundary is
// split into the exterior shell and the floaters (cavities, thesis §4.1.6).
#include <array>
#include <vector>

#include "pqmesh/plc.hpp"

namespace pqmesh {

// An edge of P: the segment between two vertices that is a side of some facet
// loop. In a valid 3D domain every edge lies on exactly two facets.
struct DomainEdge {
  int a = -1, b = -1;          // vertex ids, a < b
  std::array<int, 2> facets{-1, -1};
};

// A connected component of the boundary dP.
struct Shell {
  std::vector<int> facets;
  bool exterior = false;       // the one shell that bounds P from outside
};

struct Domain3 {
  Plc3 plc;                                   // facets oriented outward (see Facet3)
  std::vector<DomainEdge> edges;              // sorted by (a, b)
  std::vector<Shell> shells;                  // shells[0] is the exterior shell; the rest are floaters
  std::vector<Vec3> facet_normals;            // unit outward normal per facet (a construction, for reports)
  // Every facet triangulated without new vertices (facets may have holes);
  // triangles are oriented outward like their facet and grouped by facet in
  // increasing facet id, so facet_triangle_owner is non-decreasing.
  std::vector<std::array<int, 3>> facet_triangles;
  std::vector<int> facet_triangle_owner;      // facet id of each facet triangle
  double volume = 0;
  Vec3 bbox_min, bbox_max;
};

// A polygon with holes. loops[0] is the outer boundary, counter-clockwise; the
// other loops bound holes and turn clockwise, so the interior is always on the
// left. loop_segments[i][k] is the input segment id from loops[i][k] to
// loops[i][k+1] (cyclically).
struct Domain2 {
  Pslg2 pslg;
  std::vector<std::vector<int>> loops;
  std::vector<std::vector<int>> loop_segments;
  double area = 0;
  Vec2 bbox_min, bbox_max;
};

// Validate and orient. Throws DomainError (see ErrorCode) on the first class of
// violation found; the message names every offending id of that class (up to a
// reasonable cap) and the file line of the first.
Domain3 make_domain(Plc3 plc);
Domain2 make_domain(Pslg2 pslg);

enum class Location { Inside, Boundary, Outside };

// Exact point location (every decision by exact predicates).
Location locate(const Domain3& domain, Vec3 p);
Location locate(const Domain2& domain, Vec2 p);

}  // namespace pqmesh
