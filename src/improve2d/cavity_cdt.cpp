// Cavity re-triangulation by the CDT of its boundary (cavity_cdt.hpp).
#include "improve2d/cavity_cdt.hpp"

#include <algorithm>

#include "cdt2d/constrained_delaunay.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::detail {

std::vector<std::array<int, 3>> retriangulate_cavity(const std::vector<Vec2>& points,
                                                     const std::vector<std::array<int, 2>>& boundary,
                                                     std::size_t cavity_triangles, std::size_t inner_vertices) {
  if (cavity_triangles < 2 * inner_vertices + 1) return {};
  std::vector<int> ids;  // the boundary vertices, by global id (a deterministic order)
  for (const auto& e : boundary) ids.insert(ids.end(), e.begin(), e.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  auto local = [&](int v) { return int(std::lower_bound(ids.begin(), ids.end(), v) - ids.begin()); };
  cdt2d::CdtInput in;
  for (int v : ids) in.points.push_back(points[std::size_t(v)]);
  for (const auto& e : boundary) in.constraints.push_back({local(e[0]), local(e[1])});
  std::vector<std::array<int, 3>> out;
  try {
    out = cdt2d::constrained_delaunay(in, /*keep_inside=*/true).triangles;
  } catch (const InternalError&) {
    return {};  // a constraint set cdt2d rejects (never seen): the cavity is not re-triangulated
  }
  // Every constraint stays one edge (no input point lies on a mesh edge), so
  // the kept triangles tile exactly the cavity when their count is right.
  if (out.size() != cavity_triangles - 2 * inner_vertices) return {};
  for (auto& t : out)
    for (int& v : t) v = ids[std::size_t(v)];
  return out;
}

}  // namespace pqmesh::detail
