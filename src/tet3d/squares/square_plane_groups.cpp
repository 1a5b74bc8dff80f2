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

// Why reflex creases separate the pieces: near v, two pieces A and B meeting
// at a crease c bound P by the wedge of c (EdgeCone: the two planes; a flat
// edge inside a group does not change its plane). With c reflex, P there is
// the union of the two half-spaces and dP ∩ A's plane is where B's half-space
// is not: the thin exterior wedge of c lies between A's part of dP and B's,
// and S, whose closure c does not meet (c is not in m), holds both parts
// with the exterior strip between them. A piece is a plane group, or the
// groups joined by a crease of v that crosses S (then its wedge, Case B, is
// the piece: the crease's two facets are the only ones bounding it in S).
// The neighbour cells beyond S (finer or equal, outside the united box) then
// hold the pieces as separate components (a duplicated cube, §4.1.1: a facet
// box, an edge box of the crossing crease, or an edge box of a flat edge of
// the group), and each piece is triangulated by the same rule on both sides.
// A convex crease would join the two chords into one strip (Case D of c,
// whose chords would have to be keyed by the piece member holding them): not
// built, the square stays an InternalError.
std::vector<SquareDispatcher::Incidence> SquareDispatcher::crease_pieces(int vertex, const Incidence& m) {
  if (!m.vertices.empty()) return {};
  const std::vector<std::vector<int>>& groups = plane_groups(vertex);
  const auto group_of = [&](int f) {
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (std::binary_search(groups[g].begin(), groups[g].end(), f)) return g;
    return groups.size();
  };
  // Pieces: the groups met by m, joined across every crease in m; each piece
  // is named by its smallest group index, so pieces come out ordered by it.
  std::vector<std::size_t> piece(groups.size());
  std::iota(piece.begin(), piece.end(), std::size_t{0});
  const auto root = [&](std::size_t g) {
    while (piece[g] != g) g = piece[g] = piece[piece[g]];
    return g;
  };
  for (const int e : m.edges) {
    const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
    const std::size_t a = root(group_of(de.facets[0])), b = root(group_of(de.facets[1]));
    piece[std::max(a, b)] = std::min(a, b);
  }
  std::vector<std::size_t> met;
  for (const int f : m.facets) met.push_back(root(group_of(f)));
  std::sort(met.begin(), met.end());
  met.erase(std::unique(met.begin(), met.end()), met.end());
  if (met.size() < 2) return {};
  std::vector<Incidence> pieces;
  for (const std::size_t p : met) {
    Incidence one;
    for (const int f : m.facets)
      if (root(group_of(f)) == p) one.facets.push_back(f);
    for (const int e : m.edges)
      if (root(group_of(domain_.edges[static_cast<std::size_t>(e)].facets[0])) == p) one.edges.push_back(e);
    pieces.push_back(std::move(one));
  }
  // Every two pieces are apart on S: they meet at v in reflex creases only,
  // or each lies beyond the region the other's rule triangulates.
  const auto reflex_neighbours = [&](std::size_t i, std::size_t j) {
    bool meet = false;
    for (const int e : vertex_edges(vertex)) {
      const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
      const std::size_t a = root(group_of(de.facets[0])), b = root(group_of(de.facets[1]));
      if (!((a == met[i] && b == met[j]) || (a == met[j] && b == met[i]))) continue;
      if (cone(e).convex()) return false;
      meet = true;
    }
    return meet;
  };
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
      if (!reflex_neighbours(i, j) &&
          !(beyond_region(vertex, pieces[i], pieces[j]) && beyond_region(vertex, pieces[j], pieces[i])))
        return {};
  return pieces;
}

// Why this separates the two regions: the planes bounding `other`'s region
// pass through v, so a facet of `piece` whose vertices other than v all lie
// strictly beyond one of them (a half-space, or both for the union of a
// reflex wedge) lies beyond it except at v, which is not on S. If each
// piece's chords lie outside the other's region, the two regions, each one
// cell of S cut by its own chords, share no point: a common point would lie
// in a cell of S bounded by no chord at all, that is all of S.
bool SquareDispatcher::beyond_region(int vertex, const Incidence& piece, const Incidence& other) {
  const auto& pv = domain_.plc.vertices;
  const auto all_beyond = [&](const FacetPlane& plane) {
    for (const int f : piece.facets)
      for (const std::vector<int>& loop : domain_.plc.facets[static_cast<std::size_t>(f)].loops)
        for (const int w : loop)
          if (w != vertex && plane.side(pv[static_cast<std::size_t>(w)]) != Sign::Positive) return false;
    return true;
  };
  if (other.edges.empty() && other.facets.size() == 1) return all_beyond(plane(other.facets[0]));
  if (other.edges.size() != 1 || other.facets.size() != 2) return false;
  const EdgeCone& c = cone(other.edges[0]);
  if (c.flat()) return false;
  if (c.convex()) return all_beyond(c.f()) || all_beyond(c.g());
  return all_beyond(c.f()) && all_beyond(c.g());
}

}  // namespace pqmesh::tet3d
