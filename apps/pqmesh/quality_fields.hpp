#pragma once
// Per-element quality as cell data for .vtu output (io does not depend on
// quality; the CLI computes the fields and hands them to the writer).
#include <vector>

#include "pqmesh/mesh.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quality.hpp"

namespace pqmesh::cli {

inline std::vector<CellField> quality_fields(const TriMesh2& mesh) {
  const std::vector<TriQuality> q = element_quality(mesh);
  std::vector<CellField> fields = {{"aspect_ratio", {}}, {"min_angle", {}}, {"max_angle", {}}};
  for (auto& f : fields) f.values.reserve(q.size());
  for (const TriQuality& e : q) {
    fields[0].values.push_back(e.aspect_ratio);
    fields[1].values.push_back(e.min_angle_deg);
    fields[2].values.push_back(e.max_angle_deg);
  }
  return fields;
}

inline std::vector<CellField> quality_fields(const TetMesh3& mesh) {
  const std::vector<TetQuality> q = element_quality(mesh);
  std::vector<CellField> fields = {{"aspect_ratio", {}}, {"min_dihedral", {}}, {"max_dihedral", {}}};
  for (auto& f : fields) f.values.reserve(q.size());
  for (const TetQuality& e : q) {
    fields[0].values.push_back(e.aspect_ratio);
    fields[1].values.push_back(e.min_dihedral_deg);
    fields[2].values.push_back(e.max_dihedral_deg);
  }
  return fields;
}

}  // namespace pqmesh::cli
