#pragma once
// Per-element quality as cell data for .vtu output (io does not depend on
// quality; the CLI computes the fields and hands them to the writer). Computed
// element by element straight into the three fields, without a per-element
// record array: at a few million elements that array would be the process's
// peak memory. The mesh must have valid indices (it passed check_mesh, or was
// read and validated). The fields are display values, written to .vtu as
// Float32 (CellField::single_precision): half the bytes of Float64.
// Tetrahedra go through TetrahedronQualityMemo: the same tetrahedron_quality
// doubles, computed once per shape (the octree repeats a few thousand shapes).
#include <cstddef>
#include <vector>

#include "pqmesh/mesh.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quality.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::cli {

inline std::vector<CellField> quality_fields(const TriMesh2& mesh) {
  std::vector<CellField> fields = {{"aspect_ratio", {}, true}, {"min_angle", {}, true}, {"max_angle", {}, true}};
  for (auto& f : fields) f.values.resize(mesh.triangles.size());
  const auto& v = mesh.vertices;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const auto& t = mesh.triangles[e];
    const TriQuality q = triangle_quality(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                                          v[static_cast<std::size_t>(t[2])]);
    fields[0].values[e] = q.aspect_ratio;
    fields[1].values[e] = q.min_angle_deg;
    fields[2].values[e] = q.max_angle_deg;
  }
  return fields;
}

inline std::vector<CellField> quality_fields(const TetMesh3& mesh) {
  std::vector<CellField> fields = {{"aspect_ratio", {}, true}, {"min_dihedral", {}, true}, {"max_dihedral", {}, true}};
  for (auto& f : fields) f.values.resize(mesh.tetrahedra.size());
  const auto& v = mesh.vertices;
  TetrahedronQualityMemo measure;
  for (std::size_t e = 0; e < mesh.tetrahedra.size(); ++e) {
    const auto& t = mesh.tetrahedra[e];
    const TetQuality q = measure(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                                 v[static_cast<std::size_t>(t[2])], v[static_cast<std::size_t>(t[3])]);
    fields[0].values[e] = q.aspect_ratio;
    fields[1].values[e] = q.min_dihedral_deg;
    fields[2].values[e] = q.max_dihedral_deg;
  }
  return fields;
}

}  // namespace pqmesh::cli
