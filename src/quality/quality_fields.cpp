// quality_fields (pqmesh/quality_fields.hpp): every element through the shape
// memos, straight into the three arrays (filled in order, no zeroing pass).
#include "pqmesh/quality_fields.hpp"

#include <cstddef>

#include "quality/tetrahedron_quality_memo.hpp"
#include "quality/triangle_quality_memo.hpp"

namespace pqmesh {
namespace {

QualityFields reserved(std::size_t elements) {
  QualityFields f;
  f.aspect_ratio.reserve(elements);
  f.min_angle.reserve(elements);
  f.max_angle.reserve(elements);
  return f;
}

}  // namespace

QualityFields quality_fields(const TriMesh2& mesh) {
  QualityFields f = reserved(mesh.triangles.size());
  TriangleQualityMemo measure;
  const auto& v = mesh.vertices;
  for (const auto& t : mesh.triangles) {
    const TriQuality q = measure(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                                 v[static_cast<std::size_t>(t[2])]);
    f.aspect_ratio.push_back(q.aspect_ratio);
    f.min_angle.push_back(q.min_angle_deg);
    f.max_angle.push_back(q.max_angle_deg);
  }
  return f;
}

QualityFields quality_fields(const TetMesh3& mesh) {
  QualityFields f = reserved(mesh.tetrahedra.size());
  TetrahedronQualityMemo measure;
  const auto& v = mesh.vertices;
  for (const auto& t : mesh.tetrahedra) {
    const TetQuality q = measure(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                                 v[static_cast<std::size_t>(t[2])], v[static_cast<std::size_t>(t[3])]);
    f.aspect_ratio.push_back(q.aspect_ratio);
    f.min_angle.push_back(q.min_dihedral_deg);
    f.max_angle.push_back(q.max_dihedral_deg);
  }
  return f;
}

}  // namespace pqmesh
