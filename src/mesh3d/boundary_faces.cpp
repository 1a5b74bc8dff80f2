#include "mesh3d/boundary_faces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/check3d_plane.hpp"
#include "mesh3d/single_faces.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::mesh3d {

namespace {

class FacetFinder {
 public:
  explicit FacetFinder(const Domain3& d) : d_(d), tris_of_(d.plc.facets.size()), normal_(d.plc.facets.size()) {
    for (std::size_t t = 0; t < d.facet_triangles.size(); ++t)
      tris_of_[static_cast<std::size_t>(d.facet_triangle_owner[t])].push_back(static_cast<int>(t));
    for (std::size_t f = 0; f < tris_of_.size(); ++f)
      if (!tris_of_[f].empty()) {
        const auto& tri = d.facet_triangles[static_cast<std::size_t>(tris_of_[f].front())];
        normal_[f] = detail::plane_normal_signs(vtx(tri[0]), vtx(tri[1]), vtx(tri[2]));
      }
  }

  // All three vertices (mesh ids v, coordinates p) pass within_ulp_of_plane
  // for f's plane (decided on two corners of the ulp box,
  // mesh/check3d_plane.hpp: the same exact answer). Answers are cached per
  // (vertex, facet): a vertex on a facet is shared by about six boundary
  // triangles, and the test reaches exact arithmetic for points on the plane.
  bool on_plane(int f, const std::array<int, 3>& v, const std::array<Vec3, 3>& p) {
    const auto& list = tris_of_[static_cast<std::size_t>(f)];
    if (list.empty()) return false;
    const auto& tri = d_.facet_triangles[static_cast<std::size_t>(list.front())];
    const Vec3 &a = vtx(tri[0]), &b = vtx(tri[1]), &c = vtx(tri[2]);
    const std::array<Sign, 3>& n = normal_[static_cast<std::size_t>(f)];
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t key =
          (static_cast<std::uint64_t>(static_cast<std::uint32_t>(v[static_cast<std::size_t>(i)])) << 32) |
          static_cast<std::uint32_t>(f);
      auto it = cache_.find(key);
      if (it == cache_.end())
        it = cache_.emplace(key, detail::within_ulp_of_plane_at_extremes(p[static_cast<std::size_t>(i)], a, b, c, n))
                 .first;
      if (!it->second) return false;
    }
    return true;
  }

  // The projected point lies in a facet triangle of f (closed).
  bool contains(int f, Vec3 q) const {
    const Vec3 n = d_.facet_normals[static_cast<std::size_t>(f)];
    const int drop = dominant_axis(n);
    for (const int t : tris_of_[static_cast<std::size_t>(f)]) {
      const auto& tri = d_.facet_triangles[static_cast<std::size_t>(t)];
      const Vec3 &a = vtx(tri[0]), &b = vtx(tri[1]), &c = vtx(tri[2]);
      const Sign s = orient2d_projected(a, b, c, drop);
      if (s == Sign::Zero) continue;
      if (orient2d_projected(a, b, q, drop) != -s && orient2d_projected(b, c, q, drop) != -s &&
          orient2d_projected(c, a, q, drop) != -s)
        return true;
    }
    return false;
  }

 private:
  const Vec3& vtx(int v) const { return d_.plc.vertices[static_cast<std::size_t>(v)]; }
  const Domain3& d_;
  std::vector<std::vector<int>> tris_of_;
  std::vector<std::array<Sign, 3>> normal_;  // plane_normal_signs of each facet's first triangle
  std::unordered_map<std::uint64_t, bool> cache_;
};

}  // namespace

std::vector<int> add_boundary_faces(const mv3d::OctreeBuilder& builder, std::span<const std::int32_t> tet_leaf,
                                    TetMesh3& mesh) {
  const Domain3& d = builder.domain();
  const std::vector<std::int64_t> singles = single_faces(mesh.tetrahedra, static_cast<int>(mesh.vertices.size()));

  FacetFinder finder(d);
  std::vector<int> candidates;
  mesh.faces.clear();
  mesh.face_markers.clear();
  mesh.faces.reserve(singles.size());
  mesh.face_markers.reserve(singles.size());
  std::vector<int> facet_of_face;
  facet_of_face.reserve(singles.size());
  for (const std::int64_t code : singles) {
    const std::int64_t t = code / 4;
    const std::array<int, 3> f = outward_face(mesh.tetrahedra[static_cast<std::size_t>(t)], static_cast<int>(code % 4));
    const std::array<Vec3, 3> p = {mesh.vertices[static_cast<std::size_t>(f[0])],
                                   mesh.vertices[static_cast<std::size_t>(f[1])],
                                   mesh.vertices[static_cast<std::size_t>(f[2])]};
    const std::int32_t leaf = tet_leaf[static_cast<std::size_t>(t)];
    const mv3d::NodeData3& nd = builder.data(leaf);
    candidates.assign(nd.facets.begin(), nd.facets.end());
    for (const int ct : nd.cube_tris) candidates.push_back(d.facet_triangle_owner[static_cast<std::size_t>(ct)]);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    int found = -1, matches = 0;
    for (const int c : candidates)
      if (finder.on_plane(c, f, p)) {
        ++matches;
        if (found < 0) found = c;
      }
    if (matches > 1) {  // coplanar facets: the one holding the centroid
      const Vec3 g = (1.0 / 3) * (p[0] + p[1] + p[2]);
      found = -1;
      for (const int c : candidates)
        if (finder.on_plane(c, f, p) && finder.contains(c, g)) {
          found = c;
          break;
        }
    }
    if (found < 0)
      throw InternalError("mesh3d: boundary triangle (" + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " +
                          std::to_string(f[2]) + ") of tetrahedron " + std::to_string(t) + " in leaf " +
                          std::to_string(leaf) + " lies on no input facet of its leaf");
    mesh.faces.push_back(f);
    mesh.face_markers.push_back(d.plc.facets[static_cast<std::size_t>(found)].marker);
    facet_of_face.push_back(found);
  }
  return facet_of_face;
}

}  // namespace pqmesh::mesh3d
