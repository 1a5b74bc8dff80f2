// A second component of P inside a united vertex box (thesis §4.1.3, §4.5.2;
// docs/algorithm/tet3d_boxes.md "Duplicates"). A prism over a square with a
// narrow straight slot (two prongs): at the slot mouth the far wall of the slot
// passes through the united 2x2x2 box B of a mouth vertex v. Those leaves are
// duplicates of B's cells holding the far prong; they get their own jobs, and
// the vertex box must mesh only cone(v) ∩ B: the top facet, shared by both
// prongs, crosses B's outer squares on both sides of the slot, and only v's
// sector of it belongs to v's component (square_cases.cpp sector_meets);
// testing the facet by its triangles instead would also triangulate the far
// prong's top on B's squares, and check_mesh would find the mesh
// non-conforming.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "tet3d/boxes/box_jobs.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::tet3d {
namespace {

// Prism z in [0, depth] over the square [0, 1]^2 minus the slot
// [0.5 - w/2, 0.5 + w/2] x [0.5, 1] (the layout of data/3d/prongs_slot.poly,
// a shorter slot).
Plc3 slot_prism(double w, double depth) {
  const double a = 0.5 - w / 2, b = 0.5 + w / 2;
  return test::prism({{0, 0}, {1, 0}, {1, 1}, {b, 1}, {b, 0.5}, {a, 0.5}, {a, 1}, {0, 1}}, depth);
}

// Leaves meeting P inside a united box that are not its pieces (counted
// independently of box_jobs: the 8 cell centres of every vertex box).
int strangers_in_united_boxes(const mv3d::OctreeBuilder& b) {
  const OctTree& tree = b.tree();
  int count = 0;
  std::vector<std::int32_t> found;
  for (const std::int32_t n : b.leaves_by_id()) {
    const mv3d::NodeData3& d = b.data(n);
    if (!d.has_component || d.vertex_owner < 0) continue;
    const int v = d.vertex_owner;
    if (std::find(d.vertices.begin(), d.vertices.end(), v) == d.vertices.end()) continue;
    const mv3d::Cube& box = b.vertex_box(v);
    const double h = tree.side(n);
    for (int k = 0; k < 8; ++k) {
      tree.leaves_containing({box.lo.x + (0.5 + (k & 1)) * h, box.lo.y + (0.5 + ((k >> 1) & 1)) * h,
                              box.lo.z + (0.5 + (k >> 2)) * h},
                             found);
      for (const std::int32_t m : found)
        if (b.data(m).has_component && b.data(m).vertex_owner != v) ++count;
    }
  }
  return count;
}

class UnitedBoxComponent : public ::testing::TestWithParam<bool> {};

TEST_P(UnitedBoxComponent, SlotWallThroughAUnitedBox) {
  // Slot width 1/16: its far wall crosses the united boxes of the mouth
  // vertices (3 leaves, counted below). Generic grid (no input coordinate on
  // a box plane); no separating splits (39k tetrahedra instead of 600k; the
  // separated octree has the same configuration, 3 leaves).
  const Domain3 d = make_domain(slot_prism(1.0 / 16, 0.25));
  mv3d::OctreeOptions opt;
  opt.generic_grid = true;
  opt.separate = false;
  mv3d::OctreeBuilder b(d, opt);
  b.build();
  const int strangers = strangers_in_united_boxes(b);
  ASSERT_GT(strangers, 0) << "the slot wall no longer crosses a united box: the test needs another width";
  const BoxJobs jobs = box_jobs(b);
  ASSERT_TRUE(jobs.problems.empty()) << jobs.problems.size() << " problems, e.g. " << jobs.problems[0];
  const CornerSet corners(b);
  BoxMeshOptions mo;
  mo.warp = GetParam();
  const BoxMesh m = mesh_boxes(b.tree(), corners, d, jobs.jobs, mo);
  const CheckReport r = check_mesh(m.mesh, d);
  EXPECT_TRUE(r.valid()) << r.to_text();
  std::printf("slot prism: %d leaves of another component in united boxes, %zu tets, %lld vertex boxes\n", strangers,
              m.mesh.tetrahedra.size(), static_cast<long long>(m.stats.vertex));
}

INSTANTIATE_TEST_SUITE_P(Warp, UnitedBoxComponent, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "warped" : "unwarped"; });

}  // namespace
}  // namespace pqmesh::tet3d
