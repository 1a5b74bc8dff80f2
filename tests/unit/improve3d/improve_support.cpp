#include "improve_support.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "pqmesh/quality.hpp"

namespace pqmesh::test {

namespace {

struct FacetPlanes {
  explicit FacetPlanes(const Domain3& d) : domain(d), triangles(d.plc.facets.size()), normal(d.plc.facets.size()) {
    for (std::size_t t = 0; t < d.facet_triangles.size(); ++t)
      triangles[static_cast<std::size_t>(d.facet_triangle_owner[t])].push_back(t);
    for (std::size_t f = 0; f < triangles.size(); ++f)
      if (!triangles[f].empty()) {
        const auto& k = d.facet_triangles[triangles[f].front()];
        normal[f] = detail::plane_normal_signs(vertex(k[0]), vertex(k[1]), vertex(k[2]));
      }
  }
  const Vec3& vertex(int v) const { return domain.plc.vertices[static_cast<std::size_t>(v)]; }

  bool on_plane(std::size_t f, const std::array<Vec3, 3>& p) const {
    if (triangles[f].empty()) return false;
    const auto& k = domain.facet_triangles[triangles[f].front()];
    return std::all_of(p.begin(), p.end(), [&](const Vec3& q) {
      return detail::within_ulp_of_plane_at_extremes(q, vertex(k[0]), vertex(k[1]), vertex(k[2]), normal[f]);
    });
  }

  bool contains(std::size_t f, Vec3 q) const {
    const int drop = dominant_axis(domain.facet_normals[f]);
    for (const std::size_t t : triangles[f]) {
      const auto& k = domain.facet_triangles[t];
      const Vec3 &a = vertex(k[0]), &b = vertex(k[1]), &c = vertex(k[2]);
      const Sign s = orient2d_projected(a, b, c, drop);
      if (s == Sign::Zero) continue;
      if (orient2d_projected(a, b, q, drop) != -s && orient2d_projected(b, c, q, drop) != -s &&
          orient2d_projected(c, a, q, drop) != -s)
        return true;
    }
    return false;
  }

  const Domain3& domain;
  std::vector<std::vector<std::size_t>> triangles;
  std::vector<std::array<Sign, 3>> normal;
};

}  // namespace

std::vector<int> facets_of_faces(const Domain3& domain, const TetMesh3& mesh) {
  const FacetPlanes planes(domain);
  std::vector<int> out(mesh.faces.size(), -1);
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
    const auto& k = mesh.faces[i];
    const std::array<Vec3, 3> p = {mesh.vertices[static_cast<std::size_t>(k[0])],
                                   mesh.vertices[static_cast<std::size_t>(k[1])],
                                   mesh.vertices[static_cast<std::size_t>(k[2])]};
    candidates.clear();
    for (std::size_t f = 0; f < domain.plc.facets.size(); ++f)
      if (domain.plc.facets[f].marker == mesh.face_markers[i] && planes.on_plane(f, p)) candidates.push_back(f);
    if (candidates.size() == 1) {
      out[i] = static_cast<int>(candidates.front());
      continue;
    }
    const Vec3 g = (1.0 / 3) * (p[0] + p[1] + p[2]);
    for (const std::size_t f : candidates)
      if (planes.contains(f, g)) {
        out[i] = static_cast<int>(f);
        break;
      }
  }
  return out;
}

MeshFigures figures(const TetMesh3& mesh) {
  const QualityReport q = quality_report(mesh);
  MeshFigures m;
  m.tetrahedra = static_cast<std::int64_t>(mesh.tetrahedra.size());
  m.worst_aspect = q.aspect_ratio.max;
  m.min_dihedral = q.min_angle.min;
  for (const auto& t : mesh.tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        m.longest_edge = std::max(m.longest_edge, norm(mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])] -
                                                       mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(j)])]));
  return m;
}

std::vector<std::pair<int, double>> area_per_marker(const TetMesh3& mesh) {
  std::map<int, double> area;
  for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
    const auto& k = mesh.faces[i];
    const Vec3 a = mesh.vertices[static_cast<std::size_t>(k[0])], b = mesh.vertices[static_cast<std::size_t>(k[1])],
               c = mesh.vertices[static_cast<std::size_t>(k[2])];
    area[mesh.face_markers.empty() ? 0 : mesh.face_markers[i]] += 0.5 * norm(cross(b - a, c - a));
  }
  return {area.begin(), area.end()};
}

TetMesh3 octahedron_star(Vec3 first, Vec3 u) {
  TetMesh3 m;
  m.vertices = {first, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, u};
  for (const int x : {0, 1})
    for (const int y : {2, 3})
      for (const int z : {4, 5}) {
        std::array<int, 4> k{x, y, z, 6};
        const auto p = [&](int i) { return m.vertices[static_cast<std::size_t>(k[static_cast<std::size_t>(i)])]; };
        if (orient3d(p(0), p(1), p(2), p(3)) != Sign::Positive) std::swap(k[0], k[1]);
        m.tetrahedra.push_back(k);
      }
  return m;
}

}  // namespace pqmesh::test
