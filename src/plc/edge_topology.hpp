#pragma once
// Edges of P and the manifold conditions of thesis §1.4: every edge on exactly
// two facets (stage 6) and the link of every vertex a single cycle (stage 7).
#include <array>
#include <vector>

#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

struct EdgeTopology {
  std::vector<DomainEdge> edges;            // sorted by (a, b); facets[0] < facets[1]
  std::vector<std::array<bool, 2>> forward;  // facets[s] has a loop side a -> b (else b -> a)
};

// Builds the edge list and checks, in order: an edge used twice by one facet
// (SelfIntersectingFacet), OpenBoundary, NonManifoldEdge, PinchedVertex.
// Preconditions: stages 1-5 passed.
EdgeTopology build_edge_topology(const Plc3& plc);

// Index of edge (a, b) (either order) in the sorted list, or -1.
int find_edge(const std::vector<DomainEdge>& edges, int a, int b);

// Per PLC vertex: the ids of the domain edges at it and of the facets whose
// loops hold it, each list sorted and without repeats. Cost O(edges + loop
// vertices), plus the sorts.
struct VertexIncidence {
  std::vector<std::vector<int>> edges, facets;
};
VertexIncidence vertex_incidence(const Domain3& domain);

}  // namespace pqmesh::detail
