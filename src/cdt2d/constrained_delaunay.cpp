// Entry point of the cdt2d module: the phases of constrained_delaunay.hpp.
#include "cdt2d/constrained_delaunay.hpp"

#include <string>

#include "cdt2d/triangulation.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::cdt2d {

CdtOutput constrained_delaunay(const CdtInput& in, bool keep_inside) {
  const int n = static_cast<int>(in.points.size());
  for (std::size_t c = 0; c < in.constraints.size(); ++c) {
    const auto [a, b] = in.constraints[c];
    if (a < 0 || a >= n || b < 0 || b >= n || a == b)
      throw InternalError("constrained_delaunay: constraint " + std::to_string(c) + " (" + std::to_string(a) + ", " +
                          std::to_string(b) + ") is out of range or degenerate");
  }
  CdtOutput out;
  detail::Triangulation tri(in.points);
  if (!tri.build_delaunay()) return out;
  for (const auto& c : in.constraints) tri.insert_constraint(c[0], c[1]);

  std::vector<std::uint8_t> keep;
  if (keep_inside) keep = tri.inside_triangles();
  out.triangles.reserve(static_cast<std::size_t>(tri.triangle_count()) / 2 + 1);
  for (int t = 0; t < tri.triangle_count(); ++t) {
    if (tri.is_ghost(t) || (keep_inside && keep[t] == 0)) continue;
    const auto& v = tri.tri(t).v;
    out.triangles.push_back({v[0], v[1], v[2]});
  }
  return out;
}

}  // namespace pqmesh::cdt2d
