// Plane groups at a P vertex: the vertex-box dispatch of squares whose facets
// lie in several planes split into marker patches (square_cases.hpp,
// docs/algorithm/tet3d_boxes.md "Flat edges").
#include <algorithm>
#include <numeric>

#include "tet3d/squares/square_cases.hpp"

namespace pqmesh::tet3d {

// Union of v's facets over v's flat edges (exact: EdgeCone::flat).
const std::vector<std::vector<int>>& SquareDispatcher::plane_groups(int vertex) {
  const auto cached = plane_groups_.find(vertex);
  if (cached != plane_groups_.end()) return cached->second;
  const std::vector<int>& facets = vertex_facets(vertex);
  std::vector<std::size_t> parent(facets.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto index_of = [&](int f) {
    return static_cast<std::size_t>(std::lower_bound(facets.begin(), facets.end(), f) - facets.begin());
  };
  for (const int e : vertex_edges(vertex)) {
    if (!cone(e).flat()) continue;
    const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
    const std::size_t a = root(index_of(de.facets[0])), b = root(index_of(de.facets[1]));
    parent[std::max(a, b)] = std::min(a, b);
  }
  // Roots are the smallest index of their group, so groups come out ordered
  // by their smallest facet, each sorted.
  std::vector<std::vector<int>> groups;
  std::vector<std::size_t> group_of_root(facets.size(), facets.size());
  for (std::size_t i = 0; i < facets.size(); ++i) {
    const std::size_t r = root(i);
    if (group_of_root[r] == facets.size()) {
      group_of_root[r] = groups.size();
      groups.emplace_back();
    }
    groups[group_of_root[r]].push_back(facets[i]);
  }
  return plane_groups_.emplace(vertex, std::move(groups)).first->second;
}

// Why reflex creases separate the pieces: near v, two groups A and B meeting
// at a crease c bound P by the wedge of c (EdgeCone: the two planes; a flat
// edge inside a group does not change its plane). With c reflex, P there is
// the union of the two half-spaces and dP ∩ A's plane is where B's half-space
// is not: the thin exterior wedge of c lies between A's part of dP and B's,
// and S, whose closure c does not meet (c is not in m), holds both parts only
// as two chords with the exterior strip between them. The neighbour cells
// beyond S (finer or equal, outside the united box) then hold S ∩ A's
// half-space and S ∩ B's half-space as separate components (a duplicated
// cube, §4.1.1: a facet box, or an edge box of a flat edge of the group), and
// each piece is triangulated by the same rule on both sides. A convex crease
// would join the two chords into one strip (Case D of c, whose chords would
// have to be keyed by the group member holding them): not built, the square
// stays an InternalError.
std::vector<SquareDispatcher::Incidence> SquareDispatcher::plane_group_pieces(int vertex, const Incidence& m) {
  const std::vector<std::vector<int>>& groups = plane_groups(vertex);
  if (groups.size() == vertex_facets(vertex).size() || !m.vertices.empty()) return {};
  const auto group_of = [&](int f) {
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (std::binary_search(groups[g].begin(), groups[g].end(), f)) return g;
    return groups.size();
  };
  std::vector<std::size_t> met;
  for (const int f : m.facets) met.push_back(group_of(f));
  std::sort(met.begin(), met.end());
  met.erase(std::unique(met.begin(), met.end()), met.end());
  if (met.size() < 2) return {};
  for (const int e : m.edges)
    if (!cone(e).flat()) return {};
  // Every two met groups meet at v, in reflex creases only.
  for (std::size_t i = 0; i < met.size(); ++i)
    for (std::size_t j = i + 1; j < met.size(); ++j) {
      bool meet = false;
      for (const int e : vertex_edges(vertex)) {
        const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
        const std::size_t a = group_of(de.facets[0]), b = group_of(de.facets[1]);
        if (!((a == met[i] && b == met[j]) || (a == met[j] && b == met[i]))) continue;
        if (cone(e).convex()) return {};
        meet = true;
      }
      if (!meet) return {};
    }
  std::vector<Incidence> pieces;
  for (const std::size_t g : met) {
    Incidence piece;
    for (const int f : m.facets)
      if (group_of(f) == g) piece.facets.push_back(f);
    for (const int e : m.edges)
      if (group_of(domain_.edges[static_cast<std::size_t>(e)].facets[0]) == g) piece.edges.push_back(e);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

}  // namespace pqmesh::tet3d
