#pragma once
// Merging coplanar adjacent facets with equal markers (make_domain(Plc3), the
// last stage). The thesis assumes every facet of P is maximal: two facets
// meeting at an edge are not coplanar, so every edge of P is a true crease
// (§1.4; the edge cones of §4.1.4 and the Cases B/D of §4.4 need a wedge).
// Inputs often split one planar face into pieces (a ring given as four
// trapezoids, a face triangulated by a CAD exporter); TetGen merges such
// pieces by default (its -M switch turns that off). So do we:
//
//  * An edge of P is flat when the third vertex of a facet triangle of one of
//    its facets lies on the plane of the other's first facet triangle (exact
//    orient3d). Facets are oriented outward and never overlap (stages 8-9),
//    so coplanar neighbours face the same way: the dihedral angle is 180°.
//  * Facets joined by flat edges with equal markers form groups (union-find).
//    A group becomes one facet: the loop sides of its members that are not on
//    an edge between two members, chained into loops. The loop holding the
//    lexicographically smallest vertex (x, then y, then z) is loops[0]: the
//    smallest point of the group's closed region lies on its outer boundary,
//    and each hole loop lies strictly inside it. Sides keep the members'
//    outward orientation, so holes turn against loops[0] as Facet3 requires.
//  * Every input vertex stays on a facet loop, so it stays a vertex of P and
//    of every mesh (TetGen keeps every input vertex too). A group is left
//    unmerged when merging would take a vertex off every loop (all facets
//    around it are in the group) or make the merged boundary pass a vertex
//    twice (loops touching, which check_facets refuses). The flat edges left
//    (these, and those between facets with different markers) stay edges of
//    the domain; the tetrahedral mesher recovers them as 180-degree edges
//    (EdgeCone's flat form, tet3d/squares/cut_square_edge.hpp).
//
// The merged facet takes the place of the group's smallest facet id (the
// other members are removed and later ids shift down); its file line is that
// member's.
#include <optional>

#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

struct CoplanarMerge {
  Plc3 plc;           // the domain's PLC with every mergeable group as one facet
  int groups = 0;     // groups merged
  int removed = 0;    // facets removed (sum over merged groups of members - 1)
};

// nullopt when no group merges. `domain` must be a validated, oriented domain.
std::optional<CoplanarMerge> merge_coplanar_facets(const Domain3& domain);

}  // namespace pqmesh::detail
