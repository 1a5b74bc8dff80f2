// The scope of a partial trial of the warp rebuild loop (trial_scope.hpp):
// which grid points a rebuilt table changed, and which jobs' closed boxes
// hold them.
#include "tet3d/rebuild/trial_scope.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tree/root_cube.hpp"

namespace pqmesh::tet3d {
namespace {

GridPoint gp(std::int64_t x, std::int64_t y, std::int64_t z) { return GridPoint{{x, y, z}}; }

TEST(TrialScope, ChangedPointsAreAddedRemovedMovedOrRekeyedEntriesAndCopies) {
  WarpTable before, after;
  before.insert(gp(1, 0, 0), {-1, {1, 0, 0}});    // same in both
  before.insert(gp(2, 0, 0), {-1, {2, 0, 0}});    // moved
  before.insert(gp(3, 0, 0), {1, {3, 0, 0}});     // same place, another key facet
  before.insert(gp(4, 0, 0), {-1, {4, 0, 0}});    // removed
  before.insert_copy(gp(5, 0, 0), 0, {5, 0, 0});  // same copy in both
  before.insert_copy(gp(6, 0, 0), 1, {6, 0, 0});  // copy for facet 1 becomes one for facet 2
  after.insert(gp(3, 0, 0), {2, {3, 0, 0}});
  after.insert(gp(2, 0, 0), {-1, {2, 0, 0.5}});
  after.insert(gp(1, 0, 0), {-1, {1, 0, 0}});
  after.insert(gp(0, 7, 0), {-1, {0, 7, 0}});  // added
  after.insert_copy(gp(5, 0, 0), 0, {5, 0, 0});
  after.insert_copy(gp(6, 0, 0), 2, {6, 0, 0});
  const std::vector<GridPoint> expected{gp(0, 7, 0), gp(2, 0, 0), gp(3, 0, 0), gp(4, 0, 0), gp(6, 0, 0)};
  EXPECT_EQ(changed_points(before, after), expected);
  EXPECT_EQ(changed_points(after, before), expected);
  EXPECT_TRUE(changed_points(after, after).empty());
}

// The unit cube split once, then its low child once more: eight children
// (side 1/2), eight grandchildren (side 1/4).
struct TwoLevels {
  OctTree tree{RootCube<3>{{0, 0, 0}, 1}};
  std::int32_t child = -1, grandchild = -1;
  TwoLevels() {
    child = tree.split(0);
    grandchild = tree.split(child);
  }
};

TEST(TrialScope, JobsTouchedAreThoseWhoseClosedBoxHoldsAPoint) {
  TwoLevels t;
  // Jobs 0..6: children 1..7 (empty boxes); job 7: a vertex job at the
  // grandchild at child 0's high corner, its united box extending below on
  // every axis, i.e. child 0's cube.
  std::vector<BoxJob> jobs;
  for (int k = 1; k < 8; ++k) jobs.push_back({t.child + k, -1, BoxKind::Empty, -1, 0});
  jobs.push_back({t.grandchild + 7, -1, BoxKind::Vertex, 0, 7});
  const JobBoxes boxes(t.tree, jobs);

  const GridPoint centre = key_corner(t.tree.key(t.child), 7);  // the root's centre: every box
  std::vector<std::int32_t> all{0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_EQ(boxes.touching(std::vector<GridPoint>{centre}, {}), all);

  // The centre of child 0's low x face lies on the root's boundary: only
  // the united box holds it.
  GridPoint low_face = key_centre(t.tree.key(t.child));
  low_face.f[0] = 0;
  EXPECT_EQ(boxes.touching(std::vector<GridPoint>{low_face}, {}), std::vector<std::int32_t>{7});

  // The centre of the face between child 0 and child 1 (x neighbours):
  // job 0 and the united box; job 4 comes from `also`.
  GridPoint shared = key_centre(t.tree.key(t.child));
  shared.f[0] = centre.f[0];
  EXPECT_EQ(boxes.touching(std::vector<GridPoint>{shared}, std::vector<std::int32_t>{4}),
            (std::vector<std::int32_t>{0, 4, 7}));

  // A point inside child 7 only.
  const GridPoint inside = key_centre(t.tree.key(t.child + 7));
  EXPECT_EQ(boxes.touching(std::vector<GridPoint>{inside}, {}), std::vector<std::int32_t>{6});
  EXPECT_TRUE(boxes.touching({}, {}).empty());
}

}  // namespace
}  // namespace pqmesh::tet3d
