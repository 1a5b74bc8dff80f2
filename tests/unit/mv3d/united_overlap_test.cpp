// United vertex boxes (thesis §4.1.3) on the lighter octree (extended boxes
// of margin 1): overlapping_blocks on hand-made blocks, and on the data/3d
// corpus and random polyhedra the united boxes the builder records are
// pairwise disjoint (brute force) and no leaf lies in two of them.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "mv3d/united_overlap.hpp"
#include "octree_test_util.hpp"
#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"

namespace pqmesh::mv3d {
namespace {

GridBlock block(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t side) {
  return {{x, y, z}, {x + side, y + side, z + side}};
}

TEST(UnitedOverlap, TouchingBlocksDoNotOverlapSharedCellsDo) {
  // 0 and 1 touch along x = 2; 2 shares the cell [3,4]x[1,2]x[1,2] with 1;
  // 3 lies far away; 4 touches 0 at a corner only.
  const std::vector<GridBlock> blocks = {block(0, 0, 0, 2), block(2, 0, 0, 2), block(3, 1, 1, 2),
                                         block(10, 10, 10, 2), block(-2, -2, -2, 2)};
  EXPECT_EQ(overlapping_blocks(blocks), (std::vector<std::size_t>{1, 2}));
  EXPECT_TRUE(overlapping_blocks({block(0, 0, 0, 4), block(4, 4, 4, 4)}).empty());
  // One block inside another (a smaller leaf's block).
  EXPECT_EQ(overlapping_blocks({block(0, 0, 0, 4), block(1, 1, 1, 2)}), (std::vector<std::size_t>{0, 1}));
}

TEST(UnitedOverlap, BlockOfALeafExtendsBelowOnTheBitsSet) {
  const BoxKey<3> k = BoxKey<3>::cell(3, {1, 2, 3});
  const GridBlock b = united_grid_block(k, 0b101u);
  for (int a = 0; a < 3; ++a) {
    const auto i = static_cast<std::size_t>(a);
    EXPECT_EQ(b.hi[i] - b.lo[i], 2 * k.fine_side());
    EXPECT_EQ(b.lo[i], k.fine_lo(a) - (a == 1 ? 0 : k.fine_side()));
  }
}

bool interiors_meet(const Cube& a, const Cube& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y && a.lo.z < b.hi.z &&
         b.lo.z < a.hi.z;
}

// Margin 1, generic grid, no separating splits: the lightest octree of the
// 3D mesher. Returns the splits made to keep united boxes apart.
std::int64_t expect_disjoint_united_boxes(const Domain3& d, const std::string& what) {
  OctreeOptions o;
  o.extended_margin = 1;
  o.separate = false;
  o.generic_grid = true;
  OctreeBuilder b(d, o);
  b.build();
  EXPECT_TRUE(b.united_clashes().empty()) << what;
  const std::size_t n = d.plc.vertices.size();
  for (std::size_t v = 0; v < n; ++v)
    for (std::size_t w = v + 1; w < n; ++w) {
      const Cube& p = b.vertex_box(static_cast<int>(v));
      const Cube& q = b.vertex_box(static_cast<int>(w));
      if (p.lo.x > p.hi.x || q.lo.x > q.hi.x) continue;  // not centred
      EXPECT_FALSE(interiors_meet(p, q)) << what << ": vertices " << v << " and " << w;
    }
  return b.stats().splits_united;
}

TEST(UnitedOverlap, CorpusOnMarginOne) {
  for (const char* name : {"cube.poly", "l_block.poly", "fins.poly", "heat_sink.poly", "prongs_slot.poly",
                           "star_vertex.poly", "tuning_fork.poly", "wedge_5deg.poly", "plate_holes.poly"})
    expect_disjoint_united_boxes(octest::load_corpus(name), name);
}

TEST(UnitedOverlap, RandomPolyhedraOnMarginOne) {
  std::int64_t splits = 0;
  for (std::uint64_t seed = 0; seed < 24; ++seed) {
    const Domain3 d = make_domain(test::random_polyhedron(seed, test::every_run_polyhedron_options()));
    splits += expect_disjoint_united_boxes(d, test::describe_polyhedron(seed, test::every_run_polyhedron_options()));
  }
  std::printf("united-box splits over 24 seeds: %lld\n", static_cast<long long>(splits));
}

}  // namespace
}  // namespace pqmesh::mv3d
