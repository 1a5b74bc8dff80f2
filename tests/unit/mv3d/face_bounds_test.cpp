// face_bounds (cube_components.hpp), which lets the octree's crowding tests
// (thesis §4.1.3-4.1.5) skip components() of ex(b), against a reference from
// scratch: for every leaf of several octrees whose component has a facet
// triangle and whose extended box meets ∂P, the components of P ∩ ex(b) over
// all facet triangles (no candidate list, no fast path). The bounds must
// bracket the faces of b's component: sheet ⊆ component ⊆ all, and `all` must
// be exactly the union of the faces of every component.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "mv3d/octree_builder.hpp"
#include "octree_test_util.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh::mv3d {
namespace {

bool subset(const std::vector<int>& a, const std::vector<int>& b) {
  return std::includes(b.begin(), b.end(), a.begin(), a.end());
}

std::vector<int> united(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

struct Counts {
  std::int64_t boxes = 0;
  std::int64_t sheet_smaller = 0;  // the sheet misses a face of the component
  std::int64_t all_larger = 0;     // another component has a face b's lacks
};

Counts check_octree(const char* name, const Domain3& d) {
  OctreeOptions options;
  options.separate = false;  // larger leaves: more sheets and components per extended box
  OctreeBuilder b(d, options);
  b.build();
  Counts count;
  for (const std::int32_t n : b.leaves_by_id()) {
    const NodeData3& nd = b.data(n);
    if (!nd.has_component || nd.rep_triangle < 0 || nd.ex_tris.empty()) continue;
    const Cube ex = b.ex_cube(n);
    const FaceBounds fb = face_bounds(d, ex, nd.ex_tris, nd.rep_triangle);
    const CubeComponents ref = components(d, ex, /*allow_fast_path=*/false);
    const auto it = std::lower_bound(ref.triangle_component.begin(), ref.triangle_component.end(),
                                     std::pair<int, int>{nd.rep_triangle, -1});
    if (it == ref.triangle_component.end() || it->first != nd.rep_triangle) {
      ADD_FAILURE() << name << " leaf " << n << ": the representative triangle misses the extended box";
      continue;
    }
    const ComponentFaces3& mine = ref.components[static_cast<std::size_t>(it->second)];
    ComponentFaces3 every;
    for (const ComponentFaces3& c : ref.components) {
      every.vertices = united(every.vertices, c.vertices);
      every.edges = united(every.edges, c.edges);
      every.facets = united(every.facets, c.facets);
    }
    EXPECT_TRUE(subset(fb.sheet.vertices, mine.vertices)) << name << " leaf " << n << ": sheet vertices";
    EXPECT_TRUE(subset(fb.sheet.edges, mine.edges)) << name << " leaf " << n << ": sheet edges";
    EXPECT_TRUE(subset(fb.sheet.facets, mine.facets)) << name << " leaf " << n << ": sheet facets";
    EXPECT_EQ(fb.all.vertices, every.vertices) << name << " leaf " << n << ": all vertices";
    EXPECT_EQ(fb.all.edges, every.edges) << name << " leaf " << n << ": all edges";
    EXPECT_EQ(fb.all.facets, every.facets) << name << " leaf " << n << ": all facets";
    ++count.boxes;
    if (fb.sheet.vertices != mine.vertices || fb.sheet.edges != mine.edges || fb.sheet.facets != mine.facets)
      ++count.sheet_smaller;
    if (every.vertices != mine.vertices || every.edges != mine.edges || every.facets != mine.facets)
      ++count.all_larger;
  }
  std::printf("%s: %lld extended boxes, sheet smaller than the component %lld, all larger %lld\n", name,
              static_cast<long long>(count.boxes), static_cast<long long>(count.sheet_smaller),
              static_cast<long long>(count.all_larger));
  return count;
}

TEST(FaceBounds, BracketTheComponentFromScratch) {
  Counts total;
  const auto add = [&](const Counts& c) {
    total.boxes += c.boxes;
    total.sheet_smaller += c.sheet_smaller;
    total.all_larger += c.all_larger;
  };
  for (const char* name : {"l_block.poly", "tuning_fork.poly", "schoenhardt.poly", "wedge_5deg.poly"})
    add(check_octree(name, octest::load_corpus(name)));
  // A U-shaped prism (as in octree_adjacency_test.cpp): extended boxes
  // crossing the slot meet P in two components, one per prong.
  add(check_octree("u prism", make_domain(octest::extrude(
                                  {{0, 0}, {4, 0}, {4, 4}, {1.4, 4}, {1.4, 1}, {1.3, 1}, {1.3, 4}, {0, 4}}, 1))));
  // Both bounds must be strict somewhere, or the comparison could not see a
  // bound that is too tight.
  EXPECT_GT(total.boxes, 0);
  EXPECT_GT(total.sheet_smaller, 0);
  EXPECT_GT(total.all_larger, 0);
}

}  // namespace
}  // namespace pqmesh::mv3d
