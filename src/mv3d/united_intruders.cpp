// OctreeBuilder::find_united_intruders (octree_builder.hpp, united_clashes):
// on the margin-1 octree, leaves that lie in a vertex's united box B and in
// its component of P ∩ B without being pieces of B.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "mv3d/united_overlap.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::mv3d {

namespace {

bool inside(const Cube& c, const Cube& box) {
  return c.lo.x >= box.lo.x && c.lo.y >= box.lo.y && c.lo.z >= box.lo.z && c.hi.x <= box.hi.x &&
         c.hi.y <= box.hi.y && c.hi.z <= box.hi.z;
}

// The component of cc holding facet triangle t, or of mark `mark` (t < 0).
int component_of(const CubeComponents& cc, int t, std::size_t mark) {
  if (t < 0) return cc.mark_component.at(mark);
  const auto it =
      std::lower_bound(cc.triangle_component.begin(), cc.triangle_component.end(), std::pair<int, int>{t, -1});
  if (it == cc.triangle_component.end() || it->first != t)
    throw InternalError("mv3d octree: a leaf's triangle does not meet the united box holding the leaf");
  return it->second;
}

}  // namespace

// The leaves whose open cubes meet the open block: per cell of the block,
// the leaves at or below the cell's key, or the larger leaf holding it.
std::vector<std::int32_t> OctreeBuilder::leaves_in_block(std::int32_t b, int v) const {
  const GridBlock block = united_grid_block(tree_.key(b), united_below(b, v));
  const std::int32_t level = tree_.level(b);
  const std::int64_t side = tree_.key(b).fine_side();
  std::vector<std::int32_t> out, found;
  std::vector<OctTree::Key> keys;
  for (int k = 0; k < 8; ++k) {
    std::array<std::int64_t, 3> cell{};
    for (int a = 0; a < 3; ++a)
      cell[static_cast<std::size_t>(a)] = block.lo[static_cast<std::size_t>(a)] / side + ((k >> a) & 1);
    keys.assign(1, OctTree::Key::cell(level, cell));
    if (tree_.find(keys[0]) < 0) {
      const auto& key = keys[0];
      OctTree::Point centre{};
      for (int a = 0; a < 3; ++a)
        centre[static_cast<std::size_t>(a)] = 0.5 * (tree_.key_plane(key, a, false) + tree_.key_plane(key, a, true));
      tree_.leaves_containing(centre, found);
      out.insert(out.end(), found.begin(), found.end());
      continue;
    }
    while (!keys.empty()) {
      const OctTree::Key key = keys.back();
      keys.pop_back();
      bool split = false;
      for (std::int32_t n = tree_.find(key); n >= 0; n = tree_.next_same_key(n)) {
        if (tree_.is_leaf(n)) out.push_back(n);
        else split = true;
      }
      if (split)
        for (int c = 0; c < 8; ++c) keys.push_back(key.child(c));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// For each vertex v with a united box B: the leaves meeting B's interior,
// with a component, not pieces of B. One inside B whose component lies in
// v's component of P ∩ B (components() of B from the candidates of ex(b),
// which holds B on margin 1) would be meshed twice; one reaching out of B is
// not decided and counts as well (the construction is then dropped, never
// wrong).
void OctreeBuilder::find_united_intruders() {
  const std::vector<std::int32_t> vertex_leaf = vertex_leaves();
  for (std::size_t v = 0; v < vertex_leaf.size(); ++v) {
    const std::int32_t b = vertex_leaf[v];
    if (b < 0) continue;
    const Cube& box = vertex_box_[v];
    std::vector<std::int32_t> inner;
    std::vector<Vec3> marks;
    for (const std::int32_t n : leaves_in_block(b, static_cast<int>(v))) {
      const NodeData3& d = data(n);
      if (!d.has_component || d.vertex_owner == static_cast<int>(v)) continue;
      if (!inside(cube(n), box)) {
        united_clashes_.push_back({n, static_cast<int>(v), -1});
        continue;
      }
      inner.push_back(n);
      if (d.rep_triangle < 0) marks.push_back(0.5 * (cube(n).lo + cube(n).hi));
    }
    if (inner.empty()) continue;
    const NodeData3& db = data(b);
    const bool corner0 = corner0_in_from(domain_, box, ex_cube(b), db.ex_corner0_in, db.ex_tris);
    const CubeComponents cc = components(domain_, box, CubeHint{db.ex_tris, false, corner0}, true, marks);
    const int mine = component_of(cc, db.rep_triangle, 0);
    std::size_t mark = 0;
    for (const std::int32_t n : inner) {
      const int t = data(n).rep_triangle;
      if (component_of(cc, t, t < 0 ? mark++ : 0) == mine) united_clashes_.push_back({n, static_cast<int>(v), -1});
    }
  }
}

}  // namespace pqmesh::mv3d
