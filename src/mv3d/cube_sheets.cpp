// The sheets of P ∩ C and the face lists of components (cube_sheets.hpp).
#include "mv3d/cube_sheets.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "mv3d/shifted_cube.hpp"

namespace pqmesh::mv3d::detail {

int edge_index(const Domain3& dom, int a, int b) {
  if (a > b) std::swap(a, b);
  const auto it = std::lower_bound(dom.edges.begin(), dom.edges.end(), std::pair{a, b},
                                   [](const DomainEdge& e, const std::pair<int, int>& k) { return std::pair{e.a, e.b} < k; });
  if (it != dom.edges.end() && it->a == a && it->b == b) return static_cast<int>(it - dom.edges.begin());
  return -1;
}

// Fills the face lists of every component from the local triangle -> component map.
void fill_faces(const Domain3& dom, const Cube& c, std::span<const int> tris, const std::vector<int>& comp_of,
                CubeComponents& out) {
  std::vector<std::pair<std::array<int, 2>, int>> sides;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const int t = tris[i], k = comp_of[i];
    out.triangle_component.push_back({t, k});
    ComponentFaces3& f = out.components[static_cast<std::size_t>(k)];
    f.facets.push_back(dom.facet_triangle_owner[static_cast<std::size_t>(t)]);
    const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
    for (int j = 0; j < 3; ++j) {
      const int v = tri[static_cast<std::size_t>(j)], w = tri[static_cast<std::size_t>((j + 1) % 3)];
      if (vertex_inside(dom.plc.vertices[static_cast<std::size_t>(v)], c)) f.vertices.push_back(v);
      sides.push_back({{std::min(v, w), std::max(v, w)}, k});
    }
  }
  std::sort(sides.begin(), sides.end());
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  for (const auto& [s, k] : sides) {
    const int e = edge_index(dom, s[0], s[1]);
    if (e < 0) continue;
    if (!segment_meets(dom.plc.vertices[static_cast<std::size_t>(s[0])], dom.plc.vertices[static_cast<std::size_t>(s[1])], c))
      continue;
    out.components[static_cast<std::size_t>(k)].edges.push_back(e);
  }
  for (ComponentFaces3& f : out.components) {
    for (auto* v : {&f.vertices, &f.edges, &f.facets}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
  }
  std::sort(out.triangle_component.begin(), out.triangle_component.end());
}

void join_sheets(const Domain3& domain, const Cube& cube, std::span<const int> tris, UnionFind& uf) {
  const std::size_t m = tris.size();
  std::vector<std::pair<int, int>> at_vertex;                   // (vertex in C, local triangle)
  std::vector<std::pair<std::array<int, 2>, int>> at_side;      // (side, local triangle), sides with no vertex in C
  for (std::size_t i = 0; i < m; ++i) {
    const auto& tri = domain.facet_triangles[static_cast<std::size_t>(tris[i])];
    for (int j = 0; j < 3; ++j) {
      const int v = tri[static_cast<std::size_t>(j)], w = tri[static_cast<std::size_t>((j + 1) % 3)];
      const bool vin = vertex_inside(domain.plc.vertices[static_cast<std::size_t>(v)], cube);
      const bool win = vertex_inside(domain.plc.vertices[static_cast<std::size_t>(w)], cube);
      if (vin) at_vertex.push_back({v, static_cast<int>(i)});
      if (!vin && !win) at_side.push_back({{std::min(v, w), std::max(v, w)}, static_cast<int>(i)});
    }
  }
  std::sort(at_vertex.begin(), at_vertex.end());
  for (std::size_t k = 1; k < at_vertex.size(); ++k)
    if (at_vertex[k].first == at_vertex[k - 1].first) uf.unite(at_vertex[k].second, at_vertex[k - 1].second);
  std::sort(at_side.begin(), at_side.end());
  for (std::size_t k = 1; k < at_side.size(); ++k) {
    if (at_side[k].first != at_side[k - 1].first) continue;
    const auto& s = at_side[k].first;
    if (segment_meets(domain.plc.vertices[static_cast<std::size_t>(s[0])], domain.plc.vertices[static_cast<std::size_t>(s[1])], cube))
      uf.unite(at_side[k].second, at_side[k - 1].second);
  }
}

}  // namespace pqmesh::mv3d::detail
