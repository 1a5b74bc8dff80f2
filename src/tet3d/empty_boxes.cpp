#include "tet3d/empty_boxes.hpp"

#include <string>
#include <unordered_map>

#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "tet3d/box_faces.hpp"

namespace pqmesh::tet3d {

bool is_empty_inside(const mv3d::OctreeBuilder& builder, std::int32_t n) {
  const mv3d::NodeData3& d = builder.data(n);
  return d.has_component && d.rep_triangle == -1;
}

bool is_flush_inside(const mv3d::OctreeBuilder& builder, std::int32_t n) {
  if (is_empty_inside(builder, n)) return true;
  const mv3d::NodeData3& d = builder.data(n);
  if (!d.has_component) return false;
  const Domain3& dom = builder.domain();
  const mv3d::Cube c = builder.cube(n);
  const double lo[3] = {c.lo.x, c.lo.y, c.lo.z};
  const double hi[3] = {c.hi.x, c.hi.y, c.hi.z};
  for (const int t : d.cube_tris) {
    const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
    bool separated = false;
    for (int a = 0; a < 3 && !separated; ++a) {
      bool below = true, above = true;
      for (const int v : tri) {
        const Vec3& p = dom.plc.vertices[static_cast<std::size_t>(v)];
        const double x = a == 0 ? p.x : (a == 1 ? p.y : p.z);
        below = below && x <= lo[a];
        above = above && x >= hi[a];
      }
      separated = below || above;
    }
    if (!separated) return false;
  }
  // No facet meets the open cube, so it lies entirely inside or outside P;
  // its centre (an exact grid point) decides.
  return locate(dom, grid_coordinates(builder.tree(), key_centre(builder.tree().key(n)))) == Location::Inside;
}

std::vector<std::int32_t> empty_leaves(const mv3d::OctreeBuilder& builder, bool flush) {
  std::vector<std::int32_t> out;
  for (const std::int32_t n : builder.leaves_by_id())
    if (flush ? is_flush_inside(builder, n) : is_empty_inside(builder, n)) out.push_back(n);
  return out;
}

EmptyBoxMesh mesh_empty_boxes(const mv3d::OctreeBuilder& builder, std::span<const std::int32_t> leaves) {
  return mesh_empty_boxes(builder.tree(), CornerSet(builder), leaves);
}

EmptyBoxMesh mesh_empty_boxes(const OctTree& tree, const CornerSet& corners, std::span<const std::int32_t> leaves) {
  EmptyBoxMesh out;
  std::unordered_map<GridPoint, int, GridPointHash> ids;
  auto vertex = [&](const GridPoint& p) {
    const auto [it, fresh] = ids.try_emplace(p, static_cast<int>(out.keys.size()));
    if (fresh) {
      out.keys.push_back(p);
      out.mesh.vertices.push_back(grid_coordinates(tree, p));
    }
    return it->second;
  };
  std::vector<GridTriangle> tris;
  for (const std::int32_t n : leaves) {
    if (!tree.is_leaf(n)) throw InternalError("tet3d: node " + std::to_string(n) + " is not a leaf");
    const BoxKey<3>& key = tree.key(n);
    tris.clear();
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) triangulate_box_face(key, axis, upper, corners, tris);
    const int c = vertex(key_centre(key));
    for (const GridTriangle& t : tris) {
      // t's normal points out of the box and the centre lies inside, so the
      // reversed triangle followed by the centre has positive volume (mesh.hpp).
      const int a = vertex(t[0]), b = vertex(t[1]), d = vertex(t[2]);
      out.mesh.tetrahedra.push_back({a, d, b, c});
      out.tet_leaf.push_back(n);
    }
  }
  out.mesh.tetrahedron_markers.assign(out.mesh.tetrahedra.size(), 0);
  return out;
}

}  // namespace pqmesh::tet3d
