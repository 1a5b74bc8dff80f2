// Gmsh MSH 4.1 binary ("4.1 1 8"): the sections, entities, blocks, tags and
// order of the ASCII 4.1 file of mesh_gmsh.cpp, with the numbers of
// $Entities, $Nodes, $Elements and the values of $NodeData stored as
// little-endian binary as the Gmsh manual specifies: counts and node/element
// tags as size_t (8 bytes, the "8" of the header), entity tags, dimensions,
// element types and physical tags as int (4 bytes), coordinates and data
// values as double; a $NodeData entry is an int node tag and a double. The
// int 1 after the header line lets readers check the byte order.
// $PhysicalNames and the tag lines of $NodeData stay ASCII, and every binary
// part is followed by "\n" before its $End line.
#include <cstdint>

#include "io/gmsh_common.hpp"

namespace pqmesh::detail::gmsh {

namespace {

void put_size(BufferedWriter& out, std::size_t v) { out.put_le(static_cast<std::uint64_t>(v)); }
void put_int32(BufferedWriter& out, std::int64_t v) { out.put_le(static_cast<std::int32_t>(v)); }

// One $Entities record: tag, bounding box, the physical tag of the entity's
// marker (none for the extra element entity of a mesh without elements),
// no bounding entities.
void put_entity(BufferedWriter& out, std::size_t tag, const PhysicalGroups& groups, const double lo[3],
                const double hi[3]) {
  put_int32(out, static_cast<std::int64_t>(tag));
  for (int k = 0; k < 3; ++k) out.put_le(lo[k]);
  for (int k = 0; k < 3; ++k) out.put_le(hi[k]);
  const bool physical = tag - 1 < groups.markers.size();
  put_size(out, physical ? 1 : 0);
  if (physical) put_int32(out, groups.physical_tags[tag - 1]);
  put_size(out, 0);
}

// Element blocks of one kind of item, in entity order (order_by_entity);
// item i gets tag tag_offset + i + 1.
template <class Items>
void put_element_blocks(BufferedWriter& out, const Items& items, const PhysicalGroups& groups,
                        const std::vector<int>& markers, int dim, int type, std::size_t tag_offset) {
  std::vector<std::size_t> blocks;
  const std::vector<std::size_t> order = order_by_entity(groups, markers, items.size(), blocks);
  std::size_t pos = 0;
  for (std::size_t g = 0; g < blocks.size(); ++g) {
    if (blocks[g] == 0) continue;
    put_int32(out, dim);
    put_int32(out, static_cast<std::int64_t>(g + 1));
    put_int32(out, type);
    put_size(out, blocks[g]);
    for (std::size_t k = 0; k < blocks[g]; ++k, ++pos) {
      const std::size_t i = order[pos];
      put_size(out, tag_offset + i + 1);
      for (int v : items[i]) put_size(out, static_cast<std::size_t>(v) + 1);
    }
  }
}

std::size_t nonempty(const std::vector<std::size_t>& blocks) {
  std::size_t n = 0;
  for (std::size_t s : blocks) n += s > 0 ? 1 : 0;
  return n;
}

}  // namespace

template <class M>
void write_binary41(const M& mesh, BufferedWriter& out) {
  using T = MeshTraits<M>;
  constexpr int D = T::dim;
  const auto& cells = T::cells(mesh);
  const auto& faces = T::faces(mesh);
  const std::size_t nv = mesh.vertices.size(), nc = cells.size(), nf = faces.size();
  const PhysicalGroups cell_groups = make_physical_groups(T::cell_markers(mesh), nc);
  const PhysicalGroups face_groups = make_physical_groups(T::face_markers(mesh), nf);

  out.put("$MeshFormat\n4.1 1 8\n");
  put_int32(out, 1);
  out.put("\n$EndMeshFormat\n");
  put_physical_names(out, face_groups, D - 1, cell_groups, D);

  double lo[3], hi[3];
  bounding_box(mesh, lo, hi);
  const EntityCounts counts = entity_counts(D, face_groups, cell_groups, nv);
  out.put("$Entities\n");
  for (std::size_t c : counts.per_dim) put_size(out, c);
  for (std::size_t g = 1; g <= face_groups.markers.size(); ++g) put_entity(out, g, face_groups, lo, hi);
  for (std::size_t g = 1; g <= counts.cells; ++g) put_entity(out, g, cell_groups, lo, hi);
  out.put("\n$EndEntities\n");

  out.put("$Nodes\n");
  put_size(out, nv > 0 ? 1 : 0);
  put_size(out, nv);
  put_size(out, nv > 0 ? 1 : 0);
  put_size(out, nv);
  if (nv > 0) {
    put_int32(out, D);
    put_int32(out, 1);
    put_int32(out, 0);
    put_size(out, nv);
    for (std::size_t i = 0; i < nv; ++i) put_size(out, i + 1);
    for (const auto& p : mesh.vertices)
      for (int k = 0; k < 3; ++k) out.put_le(coord(p, k));
  }
  out.put("\n$EndNodes\n$Elements\n");
  std::vector<std::size_t> cell_blocks, face_blocks;
  order_by_entity(cell_groups, T::cell_markers(mesh), nc, cell_blocks);
  order_by_entity(face_groups, T::face_markers(mesh), nf, face_blocks);
  put_size(out, nonempty(cell_blocks) + nonempty(face_blocks));
  put_size(out, nc + nf);
  put_size(out, nc + nf > 0 ? 1 : 0);
  put_size(out, nc + nf);
  put_element_blocks(out, cells, cell_groups, T::cell_markers(mesh), D, D == 2 ? kTriangle : kTetrahedron, 0);
  put_element_blocks(out, faces, face_groups, T::face_markers(mesh), D - 1, D == 2 ? kLine : kTriangle, nc);
  out.put("\n$EndElements\n");

  if (!mesh.vertex_markers.empty()) {
    put_data_header(out, "NodeData", "vertex_marker", nv);
    for (std::size_t i = 0; i < nv; ++i) {
      put_int32(out, static_cast<std::int64_t>(i + 1));
      out.put_le(static_cast<double>(mesh.vertex_markers[i]));
    }
    out.put("\n$EndNodeData\n");
  }
}

template void write_binary41(const TriMesh2&, BufferedWriter&);
template void write_binary41(const TetMesh3&, BufferedWriter&);

}  // namespace pqmesh::detail::gmsh
