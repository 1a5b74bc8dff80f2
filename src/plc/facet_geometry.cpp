#include "plc/facet_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace pqmesh::detail {

bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  for (int drop = 0; drop < 3; ++drop)
    if (orient2d_projected(a, b, c, drop) != Sign::Zero) return false;
  return true;
}

int choose_drop(Vec3 a, Vec3 b, Vec3 c, Vec3 hint) {
  std::array<int, 3> axes{0, 1, 2};
  const std::array<double, 3> mag{std::abs(hint.x), std::abs(hint.y), std::abs(hint.z)};
  std::stable_sort(axes.begin(), axes.end(), [&](int i, int j) { return mag[i] > mag[j]; });
  for (int axis : axes)
    if (orient2d_projected(a, b, c, axis) != Sign::Zero) return axis;
  return -1;  // collinear: the caller checked this cannot happen
}

Vec3 newell_normal(const std::vector<Vec3>& vertices, const std::vector<int>& loop) {
  Vec3 n;
  const std::size_t m = loop.size();
  if (m == 0) return n;
  const Vec3 o = vertices[loop[0]];  // relative coordinates reduce cancellation
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3 p = vertices[loop[k]] - o, q = vertices[loop[(k + 1) % m]] - o;
    n.x += (p.y - q.y) * (p.z + q.z);
    n.y += (p.z - q.z) * (p.x + q.x);
    n.z += (p.x - q.x) * (p.y + q.y);
  }
  return n;
}

std::optional<std::array<int, 3>> find_basis(const std::vector<Vec3>& vertices, const Facet3& facet) {
  if (facet.loops.empty() || facet.loops[0].empty()) return std::nullopt;
  const int a = facet.loops[0][0];
  int b = -1;
  for (const auto& loop : facet.loops)
    for (int v : loop)
      if (b < 0 && !(vertices[v] == vertices[a])) b = v;
  if (b < 0) return std::nullopt;
  for (const auto& loop : facet.loops)
    for (int v : loop)
      if (!collinear(vertices[a], vertices[b], vertices[v])) return std::array<int, 3>{a, b, v};
  return std::nullopt;
}

ProjectedFacet project_facet(const std::vector<Vec3>& vertices, const Facet3& facet, int drop) {
  ProjectedFacet out;
  std::vector<std::pair<int, int>> ids;  // (vertex id, position) to assign local ids deterministically
  for (const auto& loop : facet.loops)
    for (int v : loop) ids.push_back({v, 0});
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  for (const auto& [v, unused] : ids) {
    out.vertex_of.push_back(v);
    out.points.push_back(project(vertices[v], drop));
  }
  auto local = [&](int v) {
    return static_cast<int>(std::lower_bound(ids.begin(), ids.end(), std::pair<int, int>{v, 0}) - ids.begin());
  };
  for (const auto& loop : facet.loops) {
    std::vector<int> l;
    l.reserve(loop.size());
    for (int v : loop) l.push_back(local(v));
    out.loops.push_back(std::move(l));
  }
  return out;
}

}  // namespace pqmesh::detail
