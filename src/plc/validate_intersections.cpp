// Stage 8 of 3D validation: facets meet only in shared edges and vertices
// (thesis §1.4; docs/algorithm/input.md "Validation, orientation and shells").
// Facets are triangulated without new vertices and candidate triangle pairs
// come from a uniform grid; every decision is an exact predicate
// (intersect_triangles.hpp).
#include <algorithm>
#include <sstream>

#include "plc/facet_triangulation.hpp"
#include "plc/intersect_triangles.hpp"
#include "plc/report_error.hpp"
#include "plc/validate3.hpp"

namespace pqmesh::detail {

FacetTriangles triangulate_facets(const Plc3& plc, const std::vector<FacetPlane>& planes) {
  FacetTriangles ft;
  for (int f = 0; f < int(plc.facets.size()); ++f)
    for (const auto& t : triangulate_facet(plc.vertices, plc.facets[f], planes[f].drop)) {
      ft.triangles.push_back(t);
      ft.owner.push_back(f);
      ft.drop.push_back(planes[f].drop);
    }
  return ft;
}

namespace {

// Rotates t so that t[0] == v.
std::array<int, 3> rotate_to(std::array<int, 3> t, int v) {
  while (t[0] != v) t = {t[1], t[2], t[0]};
  return t;
}

}  // namespace

void check_intersections(const Plc3& plc, const std::vector<DomainEdge>& edges, const FacetTriangles& ft,
                         const SurfaceLocator& surface) {
  const auto& V = plc.vertices;
  std::vector<std::pair<int, int>> conflicts;  // facet pairs
  constexpr std::size_t kCap = 64;
  auto conflicting = [&](int s, int t) {
    const int f = ft.owner[s], g = ft.owner[t];
    const auto& T = ft.triangles[s];
    const auto& U = ft.triangles[t];
    int shared[3], count = 0;
    for (int a : T)
      for (int b : U)
        if (a == b) shared[count++] = a;
    const int dt = ft.drop[s], du = ft.drop[t];
    switch (count) {
      case 0:
        return triangles_meet({V[T[0]], V[T[1]], V[T[2]]}, dt, {V[U[0]], V[U[1]], V[U[2]]}, du);
      case 1: {
        const auto a = rotate_to(T, shared[0]), b = rotate_to(U, shared[0]);
        return triangles_meet_beyond_vertex(V[a[0]], V[a[1]], V[a[2]], dt, V[b[1]], V[b[2]], du);
      }
      case 2: {
        const int e = find_edge(edges, shared[0], shared[1]);
        if (e < 0 || edges[e].facets != std::array<int, 2>{std::min(f, g), std::max(f, g)}) return true;
        int c = -1, d = -1;
        for (int x : T)
          if (x != shared[0] && x != shared[1]) c = x;
        for (int x : U)
          if (x != shared[0] && x != shared[1]) d = x;
        return triangles_overlap_beyond_edge(V[shared[0]], V[shared[1]], V[c], V[d], dt);
      }
      default:
        return true;  // the same triangle in two facets
    }
  };
  // Pairs within one facet are skipped (stage 5 covered them); ft.owner is
  // nondecreasing since facets are triangulated in order.
  surface.grid().for_each_overlapping_pair(ft.owner, [&](int s, int t) {
    if (conflicts.size() >= kCap) return;
    const int f = ft.owner[s], g = ft.owner[t];
    if (conflicting(s, t)) conflicts.push_back({std::min(f, g), std::max(f, g)});
  });
  if (conflicts.empty()) return;
  std::sort(conflicts.begin(), conflicts.end());
  conflicts.erase(std::unique(conflicts.begin(), conflicts.end()), conflicts.end());
  const SourceInfo& src = plc.source;
  std::ostringstream msg;
  msg << "facets " << file_id(src, conflicts[0].first) << " and " << file_id(src, conflicts[0].second)
      << " intersect (not in a shared edge or vertex)";
  std::vector<int> ids{conflicts[0].first, conflicts[0].second};
  if (conflicts.size() > 1) {
    msg << "; also";
    for (std::size_t k = 1; k < conflicts.size() && k < 8; ++k) {
      msg << (k > 1 ? "," : "") << " " << file_id(src, conflicts[k].first) << "/" << file_id(src, conflicts[k].second);
      ids.push_back(conflicts[k].first);
      ids.push_back(conflicts[k].second);
    }
    if (conflicts.size() > 8) msg << ", ...";
  }
  throw_domain_error(src, ErrorCode::IntersectingFacets, msg.str(), ids, IdKind::Element);
}

}  // namespace pqmesh::detail
