#pragma once
// Per-element quality as cell data for .vtu output (io does not depend on
// quality; the CLI computes the fields, pqmesh/quality_fields.hpp, and hands
// them to the writer). The fields are display values, written as Float32
// (CellField::single_precision): half the bytes of Float64.
#include <type_traits>
#include <utility>
#include <vector>

#include "pqmesh/mesh.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quality_fields.hpp"

namespace pqmesh::cli {

// 2D: aspect_ratio, min_angle, max_angle; 3D: aspect_ratio, min_dihedral, max_dihedral.
template <class Mesh>
std::vector<CellField> quality_cell_fields(const Mesh& mesh) {
  constexpr bool kTets = std::is_same_v<Mesh, TetMesh3>;
  QualityFields q = quality_fields(mesh);
  return {{"aspect_ratio", std::move(q.aspect_ratio), true},
          {kTets ? "min_dihedral" : "min_angle", std::move(q.min_angle), true},
          {kTets ? "max_dihedral" : "max_angle", std::move(q.max_angle), true}};
}

}  // namespace pqmesh::cli
