// StarChanges (collapse_retry.hpp).
#include "improve3d/collapse_retry.hpp"

#include <algorithm>
#include <cstddef>

namespace pqmesh::improve3d::detail {

void StarChanges::take(const CollapseMesh& mesh) {
  points_.resize(static_cast<std::size_t>(mesh.vertex_count()));
  for (int v = 0; v < mesh.vertex_count(); ++v) points_[static_cast<std::size_t>(v)] = mesh.point(v);
  first_.resize(static_cast<std::size_t>(mesh.tet_count()));
  for (int t = 0; t < mesh.tet_count(); ++t) first_[static_cast<std::size_t>(t)] = mesh.tet(t)[0];
}

void StarChanges::since(CollapseMesh& mesh, std::vector<int>& vertices, std::vector<std::pair<int, int>>& edges) {
  const auto n = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<std::uint8_t> changed(n, 0);
  std::vector<int> star;
  for (std::size_t v = 0; v < n; ++v) {
    const bool moved = v >= points_.size() || !(mesh.point(static_cast<int>(v)) == points_[v]);
    if (!moved || !mesh.vertex_alive(static_cast<int>(v))) continue;
    star.clear();
    mesh.tets_of(static_cast<int>(v), star);
    for (const int t : star)
      for (const int x : mesh.tet(t)) changed[static_cast<std::size_t>(x)] = 1;
  }
  // A tetrahedron deleted since take(): its first vertex recorded, the others still in place.
  for (std::size_t t = 0; t < first_.size(); ++t) {
    const auto& k = mesh.tet(static_cast<int>(t));
    if (first_[t] < 0 || k[0] >= 0) continue;
    changed[static_cast<std::size_t>(first_[t])] = 1;
    for (std::size_t i = 1; i < 4; ++i) changed[static_cast<std::size_t>(k[i])] = 1;
  }
  edges.clear();
  for (int t = static_cast<int>(first_.size()); t < mesh.tet_count(); ++t) {
    const auto& k = mesh.tet(t);
    if (k[0] < 0) continue;
    for (std::size_t a = 0; a < 4; ++a) {
      changed[static_cast<std::size_t>(k[a])] = 1;
      for (std::size_t b = a + 1; b < 4; ++b) edges.push_back(std::minmax(k[a], k[b]));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  vertices.clear();
  for (std::size_t v = 0; v < n; ++v)
    if (changed[v] != 0 && mesh.vertex_alive(static_cast<int>(v))) vertices.push_back(static_cast<int>(v));
}

}  // namespace pqmesh::improve3d::detail
