#include "tet3d/boxes/empty_boxes.hpp"

#include <vector>

#include "pqmesh/domain.hpp"
#include "tet3d/squares/box_faces.hpp"

namespace pqmesh::tet3d {

bool is_empty_inside(const mv3d::OctreeBuilder& builder, std::int32_t n) {
  const mv3d::NodeData3& d = builder.data(n);
  return d.has_component && d.rep_triangle == -1;
}

bool facets_on_cube_boundary_only(const mv3d::OctreeBuilder& builder, std::int32_t n) {
  const Domain3& dom = builder.domain();
  const mv3d::Cube c = builder.cube(n);
  const double lo[3] = {c.lo.x, c.lo.y, c.lo.z};
  const double hi[3] = {c.hi.x, c.hi.y, c.hi.z};
  for (const int t : builder.data(n).cube_tris) {
    const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
    bool separated = false;
    for (int a = 0; a < 3 && !separated; ++a) {
      bool below = true, above = true;
      for (const int v : tri) {
        const Vec3& p = dom.plc.vertices[static_cast<std::size_t>(v)];
        const double x = axis_coord(p, a);
        below = below && x <= lo[a];
        above = above && x >= hi[a];
      }
      separated = below || above;
    }
    if (!separated) return false;
  }
  return true;
}

bool is_flush_inside(const mv3d::OctreeBuilder& builder, std::int32_t n) {
  if (is_empty_inside(builder, n)) return true;
  if (!builder.data(n).has_component || !facets_on_cube_boundary_only(builder, n)) return false;
  // No facet meets the open cube, so it lies entirely inside or outside P;
  // its centre (an exact grid point) decides.
  const Domain3& dom = builder.domain();
  return locate(dom, grid_coordinates(builder.tree(), key_centre(builder.tree().key(n)))) == Location::Inside;
}

std::vector<std::int32_t> empty_leaves(const mv3d::OctreeBuilder& builder, bool flush) {
  std::vector<std::int32_t> out;
  for (const std::int32_t n : builder.leaves_by_id())
    if (flush ? is_flush_inside(builder, n) : is_empty_inside(builder, n)) out.push_back(n);
  return out;
}

namespace {

// Jobs of kind Empty for the leaves `empty` marks (their faces may be Kuhn
// faces, empty_box.cpp), FromFacet with no facet (coned from the centre
// over every face's square fans) for the others: a flush leaf may have a P
// facet on a face, whose flat edges the Kuhn diagonal could cross.
BoxMesh mesh_as_empty(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                      std::span<const std::int32_t> leaves, const std::vector<char>& empty) {
  std::vector<BoxJob> jobs;
  jobs.reserve(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i)
    jobs.push_back({leaves[i], -1, empty[i] ? BoxKind::Empty : BoxKind::FromFacet, -1, 0});
  return mesh_boxes(tree, corners, domain, jobs);
}

}  // namespace

BoxMesh mesh_empty_boxes(const mv3d::OctreeBuilder& builder, std::span<const std::int32_t> leaves) {
  std::vector<char> empty(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i) empty[i] = is_empty_inside(builder, leaves[i]) ? 1 : 0;
  return mesh_as_empty(builder.tree(), CornerSet(builder), builder.domain(), leaves, empty);
}

BoxMesh mesh_empty_boxes(const OctTree& tree, const CornerSet& corners, std::span<const std::int32_t> leaves) {
  // Empty boxes never consult the domain (only facet boxes do).
  return mesh_as_empty(tree, corners, Domain3{}, leaves, std::vector<char>(leaves.size(), 1));
}

}  // namespace pqmesh::tet3d
