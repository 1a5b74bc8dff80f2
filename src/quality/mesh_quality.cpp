// Per-element quality of a whole mesh: one flat pass, no per-element allocation.
#include <cstdint>
#include <string>

#include "pqmesh/errors.hpp"
#include "pqmesh/quality.hpp"
#include "quality/element_access.hpp"

namespace pqmesh {

std::vector<TriQuality> element_quality(const TriMesh2& mesh) {
  std::vector<TriQuality> out;
  out.reserve(mesh.triangles.size());
  TriangleQualityMemo memo;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) out.push_back(detail::quality_of_element(mesh, e, memo));
  return out;
}

std::vector<TetQuality> element_quality(const TetMesh3& mesh) {
  std::vector<TetQuality> out;
  out.reserve(mesh.tetrahedra.size());
  TetrahedronQualityMemo memo;
  for (std::size_t e = 0; e < mesh.tetrahedra.size(); ++e) out.push_back(detail::quality_of_element(mesh, e, memo));
  return out;
}

namespace detail {

void throw_bad_vertex_index(std::size_t element, int vertex, std::size_t vertex_count, const char* kind) {
  throw InvalidInput(ErrorCode::IndexOutOfRange,
                     std::string(kind) + " " + std::to_string(element) + " refers to vertex " +
                         std::to_string(vertex) + " but the mesh has " + std::to_string(vertex_count) +
                         " vertices",
                     {static_cast<std::int64_t>(element), static_cast<std::int64_t>(vertex)});
}

}  // namespace detail
}  // namespace pqmesh
