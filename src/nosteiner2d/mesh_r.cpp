// Thesis §5.3 "Triangulation of R" and §5.5.1: R is meshed by the 2D
// quadtree mesher (quad_mesh, docs/algorithm/quad2d.md), which adds Steiner
// points on dR (allowed: dR is not dP). The matching stage (§5.4) needs two
// properties of the result (§5.5.1):
//  1. every mesh edge G inside an R side F is at least a constant times
//     delta of F (the thesis states it with delta(E) of the Q face E that F
//     was shrunk from, via Theorem 30's delta_R(F) >= delta(E)/2);
//  2. any two mesh edges sharing a vertex have length ratio bounded by a
//     constant.
// They are measured here (floating point, reported, not decisions). Why the
// quadtree mesher has them: docs/algorithm/nosteiner2d.md "Meshing R".
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "nosteiner2d/stages.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {

namespace {
double length(Vec2 a, Vec2 b) { return std::hypot(b.x - a.x, b.y - a.y); }
}  // namespace

RMesh r_mesh_properties(const PolygonR& r, Domain2 domain, QuadMeshResult result) {
  RMesh out;
  out.domain = std::move(domain);
  out.result = std::move(result);
  const TriMesh2& mesh = out.result.mesh;
  out.min_angle = min_triangle_angle(mesh);

  // Property 2: over all mesh edges, per vertex the longest / shortest.
  const std::size_t nv = mesh.vertices.size();
  std::vector<double> shortest(nv, std::numeric_limits<double>::infinity()), longest(nv, 0.0);
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[std::size_t(i)], b = t[std::size_t((i + 1) % 3)];
      const double len = length(mesh.vertices[std::size_t(a)], mesh.vertices[std::size_t(b)]);
      for (int v : {a, b}) {
        shortest[std::size_t(v)] = std::min(shortest[std::size_t(v)], len);
        longest[std::size_t(v)] = std::max(longest[std::size_t(v)], len);
      }
    }
  for (std::size_t v = 0; v < nv; ++v)
    if (longest[v] > 0) out.max_incident_ratio = std::max(out.max_incident_ratio, longest[v] / shortest[v]);

  // Property 1 and the boundary form of property 2: the boundary pieces
  // (mesh.edges), each assigned to the R side that holds both of its ends
  // (the checker's rule for points rounded onto a segment).
  struct Side {
    Vec2 a, b;
    double delta;
  };
  std::vector<Side> sides;
  for (std::size_t l = 0; l < r.loops.size(); ++l) {
    const auto& lp = r.loops[l];
    for (std::size_t j = 0; j < lp.size(); ++j) sides.push_back({lp[j], lp[(j + 1) % lp.size()], r.side_delta[l][j]});
  }
  out.min_side_edge_over_delta = std::numeric_limits<double>::infinity();
  std::vector<double> b_short(nv, std::numeric_limits<double>::infinity()), b_long(nv, 0.0);
  for (const auto& e : mesh.edges) {
    const Vec2 p = mesh.vertices[std::size_t(e[0])], q = mesh.vertices[std::size_t(e[1])];
    const double len = length(p, q);
    for (const Side& s : sides)
      if (within_ulp_of_segment(p, s.a, s.b) && within_ulp_of_segment(q, s.a, s.b)) {
        out.min_side_edge_over_delta = std::min(out.min_side_edge_over_delta, len / s.delta);
        break;
      }
    for (int v : {e[0], e[1]}) {
      b_short[std::size_t(v)] = std::min(b_short[std::size_t(v)], len);
      b_long[std::size_t(v)] = std::max(b_long[std::size_t(v)], len);
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (b_long[v] > 0) out.max_boundary_ratio = std::max(out.max_boundary_ratio, b_long[v] / b_short[v]);
  return out;
}

RMesh mesh_r(const PolygonR& r, const QuadMeshOptions& options) {
  Domain2 domain = polygon_r_domain(r);
  QuadMeshResult result = quad_mesh(domain, options);
  return r_mesh_properties(r, std::move(domain), std::move(result));
}

}  // namespace pqmesh
