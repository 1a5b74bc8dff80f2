#pragma once
// The stages of 3D domain validation (make_domain(Plc3),
// docs/algorithm/input.md "Validation, orientation and shells", thesis §1.4).
// Each stage throws a DomainError for the first class of violation it finds,
// naming the offending ids; later stages rely on the earlier ones having
// passed.
#include <vector>

#include "plc/edge_topology.hpp"
#include "plc/facet_geometry.hpp"
#include "plc/point_location.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::detail {

// Stage 1: EmptyDomain, NonFinite coordinates, IndexOutOfRange loop entries.
void check_basic(const Plc3& plc);

// Stage 2: two used vertices with exactly equal coordinates.
void check_duplicate_vertices(const Plc3& plc);

// Stages 3-5: DegenerateFacet, NonPlanarFacet, SelfIntersectingFacet (loops
// crossing or touching, holes outside the outer loop or nested). On success
// every hole loop is reversed if needed to turn against loops[0], so all loop
// sides of a facet agree with its right-hand normal. Returns each facet's plane.
std::vector<FacetPlane> check_facets(Plc3& plc);

// Every facet triangulated (facet_triangulation.hpp); triangles turn like
// their facet's loops[0]; drop[t] is the facet's projection axis.
struct FacetTriangles {
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> owner;
  std::vector<int> drop;
};
FacetTriangles triangulate_facets(const Plc3& plc, const std::vector<FacetPlane>& planes);

// Stage 8: IntersectingFacets. Triangles of different facets may meet only in
// a common vertex, or along a common edge that is an edge of P shared by
// exactly their two facets.
void check_intersections(const Plc3& plc, const std::vector<DomainEdge>& edges, const FacetTriangles& ft,
                         const SurfaceLocator& surface);

// Stage 9: orientation, shells and floaters (thesis §4.1.6).
struct ShellOrientation {
  std::vector<char> flip;     // per facet: reverse its loops
  std::vector<Shell> shells;  // shells[0] exterior, then floaters by first facet id
};
ShellOrientation orient_shells(const Plc3& plc, const EdgeTopology& topo, const FacetTriangles& ft,
                               const SurfaceLocator& surface);

}  // namespace pqmesh::detail
