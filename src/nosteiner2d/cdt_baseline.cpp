// Baseline: the constrained Delaunay triangulation of the input without any
// Steiner point (thesis §2.1: Lawson's flips make it maximise the min angle
// among all triangulations of the same vertices and constraints).
#include <algorithm>
#include <limits>

#include "cdt2d/constrained_delaunay.hpp"
#include "improve2d/triangle_angles.hpp"
#include "nosteiner2d/stages.hpp"

namespace pqmesh {

TriMesh2 steiner_free_cdt(const Domain2& domain) {
  cdt2d::CdtInput in;
  in.points = domain.pslg.vertices;
  for (const auto& loop : domain.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) in.constraints.push_back({loop[k], loop[(k + 1) % loop.size()]});
  TriMesh2 mesh;
  mesh.vertices = domain.pslg.vertices;
  mesh.triangles = cdt2d::constrained_delaunay(in, /*keep_inside=*/true).triangles;
  return mesh;
}

double min_triangle_angle(const TriMesh2& mesh) {
  double m = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles)
    m = std::min(m, detail::min_angle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
  return m;
}

double cdt_min_angle(const Domain2& domain) { return min_triangle_angle(steiner_free_cdt(domain)); }

}  // namespace pqmesh
