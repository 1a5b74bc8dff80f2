// Stage 4 of the tetrahedral-mesh checker, the parts that are not about
// facets: input vertices found by exact coordinates, input edges walked along
// boundary edges (check3d.cpp (b)), Steiner points on the boundary, and the
// locate() second opinion.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/check3d_stages.hpp"
#include "plc/point_location.hpp"

namespace pqmesh::detail::check3d {

void Checker3::map_input_vertices(const Domain3& d) {
  const auto& pv = d.plc.vertices;
  std::vector<char> referenced(pv.size(), 0);
  for (const auto& f : d.plc.facets)
    for (const auto& loop : f.loops)
      for (int v : loop)
        if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
  const int unreferenced =
      map_input_vertices_by_coordinates(sink_, m_.vertices, order_, pv, referenced, in2mesh_, mesh2in_);
  if (unreferenced)
    sink_.note(std::to_string(unreferenced) + " input vertices on no facet were not required to be mesh vertices");
}

// Walk every input edge along boundary edges (check3d.cpp, stage 4 (b)).
void Checker3::walk_edges(const Domain3& d) {
  const auto& pv = d.plc.vertices;
  const std::size_t ne = d.edges.size();
  chain_offset_.assign(ne + 1, 0);
  chain_items_.clear();
  edge_ok_.assign(ne, 0);
  int skipped = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    chain_offset_[e] = static_cast<int>(chain_items_.size());
    const DomainEdge& de = d.edges[e];
    const bool ids_ok = de.a >= 0 && de.b >= 0 && de.a < static_cast<int>(pv.size()) &&
                        de.b < static_cast<int>(pv.size());
    const int A = ids_ok ? in2mesh_[de.a] : -1, B = ids_ok ? in2mesh_[de.b] : -1;
    if (A < 0 || B < 0) {
      ++skipped;
      continue;
    }
    const Vec3 pa = m_.vertices[A], pb = m_.vertices[B];
    const ChainWalk walk = walk_chain(faces_.boundary_adjacency, A, B, [&](int c, int w) {
      const Vec3 p = m_.vertices[w];
      // On the edge exactly or within an ulp (docs/algorithm/quality.md "The
      // validity checker"), and onward.
      return within_ulp_of_segment(p, pa, pb) && dot_sign(p, m_.vertices[c], pb) == Sign::Negative;
    });
    const int c = walk.chain.back();
    const std::string edge_name = "input edge (" + std::to_string(de.a) + " " + std::to_string(de.b) + ")";
    if (walk.end == ChainWalk::End::Stuck) {
      sink_.add(CheckKind::MissingEdge, {de.a, de.b},
                edge_name + " is not a chain of mesh edges: no boundary edge continues along it from mesh vertex " +
                    std::to_string(c) + " at " + format_point(m_.vertices[c]) + " towards mesh vertex " +
                    std::to_string(B));
      continue;
    }
    if (walk.end == ChainWalk::End::Forked) {
      sink_.add(CheckKind::NonConforming, {c, walk.next, walk.other},
                "boundary edges from vertex " + std::to_string(c) + " to " + std::to_string(walk.next) + " and " +
                    std::to_string(walk.other) + " both run along " + edge_name + " (overlapping edges)");
      continue;
    }
    edge_ok_[e] = 1;
    chain_items_.insert(chain_items_.end(), walk.chain.begin(), walk.chain.end());
  }
  chain_offset_[ne] = static_cast<int>(chain_items_.size());
  // Edges with failed walks keep an empty chain: make offsets consistent.
  if (skipped) sink_.note(std::to_string(skipped) + " input edge(s) not walked because an endpoint is missing");
}

void Checker3::check_steiner() {
  std::vector<char> seen(m_.vertices.size(), 0);
  std::vector<int> steiner;
  for (const auto& f : faces_.boundary)
    for (int v : f)
      if (!seen[v]) {
        seen[v] = 1;
        if (mesh2in_[v] < 0) steiner.push_back(v);
      }
  std::sort(steiner.begin(), steiner.end());
  for (int v : steiner)
    sink_.add(CheckKind::SteinerOnBoundary, {v},
              "mesh vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) +
                  " is on the domain boundary but is not an input vertex");
}

// The public locate(Domain3, p) scans every facet triangle; the plc
// module's indexed locator answers the same exact question per vertex fast.
void Checker3::check_located(const Domain3& d) {
  if (d.facet_triangles.empty()) {
    sink_.note("vertex location skipped: the domain has no facet triangles (not built by make_domain?)");
    return;
  }
  // Vertices of boundary triangles assigned to a facet are on the boundary
  // by stage 4 (a rounded Steiner point may lie an ulp outside;
  // on_facet_plane accepted it).
  std::vector<char> on_facet(m_.vertices.size(), 0);
  for (std::size_t i = 0; i < faces_.boundary.size() && i < assigned_.size(); ++i)
    if (assigned_[i] >= 0)
      for (const int v : faces_.boundary[i]) on_facet[static_cast<std::size_t>(v)] = 1;
  const DomainLocator3 locator(d);
  for (std::size_t v = 0; v < m_.vertices.size(); ++v)
    if (!on_facet[v] && locator.locate(m_.vertices[v]) == Location::Outside)
      sink_.add(CheckKind::VertexOutside, {static_cast<std::int64_t>(v)},
                "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " is outside the domain");
}

}  // namespace pqmesh::detail::check3d
