#include "plc/merge_coplanar.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>
#include <vector>

#include "plc/edge_topology.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

bool lex_less(Vec3 a, Vec3 b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }

// One oriented loop side of a group member (the merged region on its left,
// seen from outside P).
struct Side {
  int from, to;
};

// The loops of the merged facet of `members`, or nothing when the group must
// stay unmerged (see the header).
std::optional<std::vector<std::vector<int>>> merged_loops(const Domain3& d, const std::vector<int>& members,
                                                          const std::vector<int>& group_of, int group) {
  std::vector<Side> sides;
  std::vector<int> loop_vertices;
  for (const int f : members)
    for (const auto& loop : d.plc.facets[f].loops) {
      const std::size_t n = loop.size();
      for (std::size_t k = 0; k < n; ++k) {
        const int u = loop[k], w = loop[(k + 1) % n];
        loop_vertices.push_back(u);
        const int e = find_edge(d.edges, u, w);
        const DomainEdge& de = d.edges[static_cast<std::size_t>(e)];
        if (group_of[de.facets[0]] == group && group_of[de.facets[1]] == group) continue;  // inside the group
        sides.push_back({u, w});
      }
    }
  // Each boundary vertex starts exactly one side (else the boundary touches
  // itself there), and every member vertex is on the boundary.
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.from < b.from; });
  for (std::size_t i = 1; i < sides.size(); ++i)
    if (sides[i].from == sides[i - 1].from) return std::nullopt;
  auto side_from = [&](int v) {
    const auto it = std::lower_bound(sides.begin(), sides.end(), v, [](const Side& s, int x) { return s.from < x; });
    return it != sides.end() && it->from == v ? static_cast<std::size_t>(it - sides.begin()) : sides.size();
  };
  for (const int v : loop_vertices)
    if (side_from(v) == sides.size()) return std::nullopt;

  // Chain into cycles, each started at its smallest vertex id (sides are
  // sorted by start vertex, so the first unused side starts a new cycle there).
  std::vector<std::vector<int>> loops;
  std::vector<char> used(sides.size(), 0);
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (used[i]) continue;
    // On a closed, consistently oriented surface as many group boundary
    // sides end at a vertex as start there, so the walk closes at side i.
    std::vector<int> loop;
    std::size_t j = i;
    while (j < sides.size() && !used[j]) {
      used[j] = 1;
      loop.push_back(sides[j].from);
      j = side_from(sides[j].to);
    }
    if (j != i) return std::nullopt;
    loops.push_back(std::move(loop));
  }
  // The outer loop holds the lexicographically smallest vertex.
  std::size_t outer = 0;
  Vec3 best{};
  bool any = false;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const int v : loops[l]) {
      const Vec3 p = d.plc.vertices[static_cast<std::size_t>(v)];
      if (!any || lex_less(p, best)) {
        best = p;
        outer = l;
        any = true;
      }
    }
  std::rotate(loops.begin(), loops.begin() + static_cast<std::ptrdiff_t>(outer),
              loops.begin() + static_cast<std::ptrdiff_t>(outer) + 1);
  return loops;
}

}  // namespace

std::optional<CoplanarMerge> merge_coplanar_facets(const Domain3& d) {
  const int nf = static_cast<int>(d.plc.facets.size());
  const auto& pv = d.plc.vertices;
  // First facet triangle of each facet (its plane), and per edge the third
  // vertex of a triangle of facets[1] on it.
  std::vector<int> first_tri(static_cast<std::size_t>(nf), -1);
  std::vector<int> wing(d.edges.size(), -1);
  for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
    const int owner = d.facet_triangle_owner[t];
    if (first_tri[owner] < 0) first_tri[owner] = static_cast<int>(t);
    const auto& tri = d.facet_triangles[t];
    for (std::size_t k = 0; k < 3; ++k) {
      const int e = find_edge(d.edges, tri[k], tri[(k + 1) % 3]);
      if (e >= 0 && d.edges[static_cast<std::size_t>(e)].facets[1] == owner) wing[e] = tri[(k + 2) % 3];
    }
  }
  std::vector<int> parent(static_cast<std::size_t>(nf));
  std::iota(parent.begin(), parent.end(), 0);
  bool any = false;
  for (std::size_t e = 0; e < d.edges.size(); ++e) {
    const int f = d.edges[e].facets[0], g = d.edges[e].facets[1];
    if (f < 0 || g < 0 || wing[e] < 0 || first_tri[f] < 0) continue;
    if (d.plc.facets[f].marker != d.plc.facets[g].marker) continue;
    const auto& t = d.facet_triangles[static_cast<std::size_t>(first_tri[f])];
    if (orient3d(pv[t[0]], pv[t[1]], pv[t[2]], pv[wing[e]]) != Sign::Zero) continue;
    parent[find_root(parent, f)] = find_root(parent, g);
    any = true;
  }
  if (!any) return std::nullopt;

  std::vector<int> group_of(static_cast<std::size_t>(nf));
  std::vector<std::vector<int>> members(static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    group_of[f] = find_root(parent, f);
    members[group_of[f]].push_back(f);  // increasing facet ids
  }
  CoplanarMerge out;
  out.plc = d.plc;
  out.plc.facets.clear();
  out.plc.source.element_line.clear();
  const SourceInfo& src = d.plc.source;
  std::vector<char> merged(static_cast<std::size_t>(nf), 0);  // per group root
  for (int f = 0; f < nf; ++f) {
    const std::vector<int>& group = members[group_of[f]];
    std::optional<std::vector<std::vector<int>>> loops;
    if (group.size() > 1) {
      if (group.front() != f) {
        if (merged[group_of[f]]) continue;  // a later member of a merged group: gone
      } else {
        loops = merged_loops(d, group, group_of, group_of[f]);
        merged[group_of[f]] = loops.has_value();
      }
    }
    Facet3 facet = d.plc.facets[f];
    if (loops) {
      facet.loops = std::move(*loops);
      ++out.groups;
      out.removed += static_cast<int>(group.size()) - 1;
    }
    out.plc.facets.push_back(std::move(facet));
    if (!src.element_line.empty()) out.plc.source.element_line.push_back(src.line_of_element(f));
  }
  if (out.groups == 0) return std::nullopt;
  return out;
}

}  // namespace pqmesh::detail
