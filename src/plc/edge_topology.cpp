#include "plc/edge_topology.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <tuple>

#include "plc/report_error.hpp"

namespace pqmesh::detail {

namespace {

// One loop side of a facet, with the corners (global loop-position ids) at its
// smaller and larger vertex.
struct Side {
  int a, b;  // a < b
  int facet;
  bool forward;
  int corner_a, corner_b;
};

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

}  // namespace

int find_edge(const std::vector<DomainEdge>& edges, int a, int b) {
  if (a > b) std::swap(a, b);
  const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair<int, int>{a, b},
                                   [](const DomainEdge& e, const std::pair<int, int>& k) {
                                     return e.a < k.first || (e.a == k.first && e.b < k.second);
                                   });
  return it != edges.end() && it->a == a && it->b == b ? static_cast<int>(it - edges.begin()) : -1;
}

EdgeTopology build_edge_topology(const Plc3& plc) {
  const SourceInfo& src = plc.source;
  std::vector<Side> sides;
  std::vector<int> corner_vertex;
  for (int f = 0; f < int(plc.facets.size()); ++f)
    for (const auto& loop : plc.facets[f].loops) {
      const int base = static_cast<int>(corner_vertex.size());
      const int n = static_cast<int>(loop.size());
      for (int k = 0; k < n; ++k) {
        corner_vertex.push_back(loop[k]);
        const int u = loop[k], w = loop[(k + 1) % n];
        const int cu = base + k, cw = base + (k + 1) % n;
        if (u < w)
          sides.push_back({u, w, f, true, cu, cw});
        else
          sides.push_back({w, u, f, false, cw, cu});
      }
    }
  std::sort(sides.begin(), sides.end(), [](const Side& s, const Side& t) {
    return std::tie(s.a, s.b, s.facet, s.corner_a) < std::tie(t.a, t.b, t.facet, t.corner_a);
  });

  EdgeTopology topo;
  std::vector<int> twice, open_facets, nonmanifold_facets;
  std::ostringstream open_msg, nm_msg;
  std::vector<int> parent(corner_vertex.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b) ++j;
    const std::size_t count = j - i;
    bool same_facet = false;
    for (std::size_t k = i + 1; k < j; ++k) same_facet = same_facet || sides[k].facet == sides[k - 1].facet;
    std::ostringstream edge_out;
    edge_out << '(' << file_id(src, sides[i].a) << ", " << file_id(src, sides[i].b) << ')';
    const std::string edge_name = edge_out.str();
    if (same_facet) {
      twice.push_back(sides[i].facet);
    } else if (count == 1) {
      if (open_facets.empty())
        open_msg << "edge " << edge_name << " lies on only one facet, " << file_id(src, sides[i].facet)
                 << ": the boundary is not closed";
      open_facets.push_back(sides[i].facet);
    } else if (count > 2) {
      std::vector<int> fs;
      for (std::size_t k = i; k < j; ++k) fs.push_back(sides[k].facet);
      if (nonmanifold_facets.empty())
        nm_msg << "edge " << edge_name << " lies on " << count << " facets: " << id_list(src, fs);
      nonmanifold_facets.insert(nonmanifold_facets.end(), fs.begin(), fs.end());
    } else {
      const Side& s = sides[i];
      const Side& t = sides[i + 1];
      DomainEdge e;
      e.a = s.a;
      e.b = s.b;
      e.facets = {s.facet, t.facet};
      topo.edges.push_back(e);
      topo.forward.push_back({s.forward, t.forward});
      // The two facets' corners at each end belong to the same link cycle.
      parent[find_root(parent, s.corner_a)] = find_root(parent, t.corner_a);
      parent[find_root(parent, s.corner_b)] = find_root(parent, t.corner_b);
    }
    i = j;
  }
  if (!twice.empty())
    throw_domain_error(src, ErrorCode::SelfIntersectingFacet,
                       "facets " + id_list(src, twice) + " use the same edge twice (the facet touches itself)",
                       twice, IdKind::Element);
  if (!open_facets.empty()) {
    if (open_facets.size() > 1) open_msg << " (facets with open edges: " << id_list(src, open_facets) << ")";
    throw_domain_error(src, ErrorCode::OpenBoundary, open_msg.str(), open_facets, IdKind::Element);
  }
  if (!nonmanifold_facets.empty())
    throw_domain_error(src, ErrorCode::NonManifoldEdge, nm_msg.str(), nonmanifold_facets, IdKind::Element);

  // Stage 7: every corner has two sides, each joining it to one other corner at
  // the same vertex, so the corners at a vertex form cycles; a single cycle
  // (one union-find set) is the §1.4 condition that P near v minus v is connected.
  const int nv = static_cast<int>(plc.vertices.size());
  std::vector<int> root_of(nv, -1);
  std::vector<char> pinched(nv, 0);
  for (std::size_t c = 0; c < corner_vertex.size(); ++c) {
    const int v = corner_vertex[c];
    const int r = find_root(parent, static_cast<int>(c));
    if (root_of[v] < 0)
      root_of[v] = r;
    else if (root_of[v] != r)
      pinched[v] = 1;
  }
  std::vector<int> bad;
  for (int v = 0; v < nv; ++v)
    if (pinched[v]) bad.push_back(v);
  if (!bad.empty())
    throw_domain_error(src, ErrorCode::PinchedVertex,
                       "vertices " + id_list(src, bad) +
                           " are pinched: the facets around each do not form a single cycle (thesis §1.4)",
                       bad, IdKind::Vertex);
  return topo;
}

VertexIncidence vertex_incidence(const Domain3& domain) {
  const std::size_t nv = domain.plc.vertices.size();
  VertexIncidence in{std::vector<std::vector<int>>(nv), std::vector<std::vector<int>>(nv)};
  for (std::size_t e = 0; e < domain.edges.size(); ++e) {  // increasing ids: each list comes sorted
    in.edges[static_cast<std::size_t>(domain.edges[e].a)].push_back(static_cast<int>(e));
    in.edges[static_cast<std::size_t>(domain.edges[e].b)].push_back(static_cast<int>(e));
  }
  for (std::size_t f = 0; f < domain.plc.facets.size(); ++f)
    for (const auto& loop : domain.plc.facets[f].loops)
      for (const int v : loop) in.facets[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
  for (auto& list : in.facets) list.erase(std::unique(list.begin(), list.end()), list.end());  // f increasing
  return in;
}

}  // namespace pqmesh::detail
