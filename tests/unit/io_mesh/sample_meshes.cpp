#include "sample_meshes.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <map>

namespace pqmesh::test {

TriMesh2 square_mesh(bool with_markers) {
  const double a = 0.1, s = 1.0 / 3.0;
  TriMesh2 m;
  m.vertices = {{a, a}, {a + s, a}, {a + s, a + s}, {a, a + s}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  if (with_markers) {
    m.vertex_markers = {1, 0, 3, -4};
    m.triangle_markers = {7, -2};
    m.edge_markers = {1, 2, 3, 4};
  }
  return m;
}

TetMesh3 cube_mesh(bool with_markers) {
  TetMesh3 m;
  const double off = 1.0 / 3.0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) m.vertices.push_back({off + 0.1 * i, off + 0.1 * j, off + 0.1 * k});
  // Path 0 -> e_a -> e_a + e_b -> 7 for each order (a, b, c) of the axes.
  // det(e_a, e_a + e_b, (1,1,1)) = sign of the permutation (a, b, c), so odd
  // permutations swap the last two vertices (hand computation, checked by
  // the Orientation test with orient3d).
  const int bit[3] = {1, 2, 4};
  const std::array<std::array<int, 3>, 6> perms = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}}};
  for (int p = 0; p < 6; ++p) {
    const int a = bit[perms[p][0]], b = a + bit[perms[p][1]];
    if (p < 3)
      m.tetrahedra.push_back({0, a, b, 7});
    else
      m.tetrahedra.push_back({0, a, 7, b});
  }
  // Boundary triangles: faces of exactly one tetrahedron, outward as in
  // (b,c,d), (a,d,c), (a,b,d), (a,c,b) for a positive tetrahedron (a,b,c,d).
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> seen;
  for (const auto& t : m.tetrahedra) {
    const std::array<std::array<int, 3>, 4> faces = {
        {{t[1], t[2], t[3]}, {t[0], t[3], t[2]}, {t[0], t[1], t[3]}, {t[0], t[2], t[1]}}};
    for (const auto& f : faces) {
      auto key = f;
      std::sort(key.begin(), key.end());
      auto& entry = seen[key];
      ++entry.first;
      entry.second = f;
    }
  }
  for (const auto& [key, entry] : seen) {
    if (entry.first != 1) continue;
    m.faces.push_back(entry.second);
    // Side: the axis on which all three corners agree, and its value.
    int side = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const int v0 = (key[0] & bit[axis]) != 0, v1 = (key[1] & bit[axis]) != 0, v2 = (key[2] & bit[axis]) != 0;
      if (v0 == v1 && v1 == v2) side = 1 + 2 * axis + v0;
    }
    m.face_markers.push_back(side);
  }
  if (with_markers) {
    m.tetrahedron_markers = {1, 2, 3, 0, -5, 2};
    for (int i = 0; i < 8; ++i) m.vertex_markers.push_back(i % 3);
  } else {
    m.face_markers.clear();
  }
  return m;
}

std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("pqmesh_io_mesh_" + name + "_" + std::to_string(static_cast<long long>(::getpid())));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace pqmesh::test
