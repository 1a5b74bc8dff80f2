#pragma once
// Bounds-checked access to the corners of one mesh element, shared by
// element_quality() and quality_report() so that both check the same way.
#include <cstddef>

#include "pqmesh/mesh.hpp"
#include "pqmesh/quality.hpp"
#include "quality/tetrahedron_quality_memo.hpp"
#include "quality/triangle_quality_memo.hpp"

namespace pqmesh::detail {

[[noreturn]] void throw_bad_vertex_index(std::size_t element, int vertex, std::size_t vertex_count,
                                         const char* kind);

inline TriQuality quality_of_element(const TriMesh2& mesh, std::size_t e) {
  const auto& t = mesh.triangles[e];
  const std::size_t n = mesh.vertices.size();
  for (int v : t) {
    if (v < 0 || static_cast<std::size_t>(v) >= n) throw_bad_vertex_index(e, v, n, "triangle");
  }
  return triangle_quality(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
}

// The same through a shape memo (the same numbers; faster over a whole mesh).
inline TriQuality quality_of_element(const TriMesh2& mesh, std::size_t e, TriangleQualityMemo& memo) {
  const auto& t = mesh.triangles[e];
  const std::size_t n = mesh.vertices.size();
  for (int v : t) {
    if (v < 0 || static_cast<std::size_t>(v) >= n) throw_bad_vertex_index(e, v, n, "triangle");
  }
  return memo(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
}

inline TetQuality quality_of_element(const TetMesh3& mesh, std::size_t e) {
  const auto& t = mesh.tetrahedra[e];
  const std::size_t n = mesh.vertices.size();
  for (int v : t) {
    if (v < 0 || static_cast<std::size_t>(v) >= n) throw_bad_vertex_index(e, v, n, "tetrahedron");
  }
  return tetrahedron_quality(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]);
}

// The same through a shape memo (the same numbers; faster over a whole mesh).
inline TetQuality quality_of_element(const TetMesh3& mesh, std::size_t e, TetrahedronQualityMemo& memo) {
  const auto& t = mesh.tetrahedra[e];
  const std::size_t n = mesh.vertices.size();
  for (int v : t) {
    if (v < 0 || static_cast<std::size_t>(v) >= n) throw_bad_vertex_index(e, v, n, "tetrahedron");
  }
  return memo(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]);
}

}  // namespace pqmesh::detail
