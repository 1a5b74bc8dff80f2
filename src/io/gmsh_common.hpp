#pragma once
// Pieces shared by the ASCII (mesh_gmsh.cpp) and binary
// (mesh_gmsh_binary.cpp) Gmsh writers: element type numbers, the entity
// order of items, the $PhysicalNames and $NodeData headers (ASCII in both
// kinds of file) and the bounding box every entity gets.
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "io/mesh_common.hpp"
#include "io/mesh_output.hpp"

namespace pqmesh::detail::gmsh {

inline constexpr int kLine = 1, kTriangle = 2, kTetrahedron = 4, kPoint = 15;

// Items (elements or boundary items) in entity order: a counting sort by
// entity that keeps index order inside each entity. block_sizes[g] is the
// number of items of entity g + 1.
std::vector<std::size_t> order_by_entity(const PhysicalGroups& groups, const std::vector<int>& markers,
                                         std::size_t count, std::vector<std::size_t>& block_sizes);

// "$PhysicalNames" ... "$EndPhysicalNames\n": one "marker <m>" group per
// (dimension, marker).
void put_physical_names(BufferedWriter& out, const PhysicalGroups& faces, int face_dim, const PhysicalGroups& cells,
                        int cell_dim);

// "$<section>" and its tags up to the item count line: one string tag
// (name), one real tag (time 0), three integer tags (step 0, 1 component,
// count).
void put_data_header(BufferedWriter& out, const char* section, const std::string& name, std::size_t count);

// The mesh's bounding box (all zero for an empty mesh; z = 0 in 2D).
template <class M>
void bounding_box(const M& mesh, double lo[3], double hi[3]) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = hi[k] = mesh.vertices.empty() ? 0.0 : coord(mesh.vertices[0], k);
    for (const auto& p : mesh.vertices) {
      lo[k] = std::min(lo[k], coord(p, k));
      hi[k] = std::max(hi[k], coord(p, k));
    }
  }
}

// The $Entities counts of a dim-D mesh with nv vertices: per dimension 0..3
// the number of entities, and the element entities among them.
struct EntityCounts {
  std::size_t per_dim[4] = {0, 0, 0, 0};
  std::size_t cells = 0;
};
inline EntityCounts entity_counts(int dim, const PhysicalGroups& faces, const PhysicalGroups& cells, std::size_t nv) {
  EntityCounts counts;
  // The nodes live in element entity 1, which must exist even without elements.
  counts.cells = std::max<std::size_t>(cells.markers.size(), nv > 0 ? 1 : 0);
  counts.per_dim[dim - 1] = faces.markers.size();
  counts.per_dim[dim] = counts.cells;
  return counts;
}

// Binary MSH 4.1 (mesh_gmsh_binary.cpp).
template <class M>
void write_binary41(const M& mesh, BufferedWriter& out);

}  // namespace pqmesh::detail::gmsh
