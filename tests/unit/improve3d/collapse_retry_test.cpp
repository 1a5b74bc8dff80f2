// StarChanges (src/improve3d/collapse_retry.hpp): the vertices whose stars
// changed and the edges made, on a hand-built mesh where both are known.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "improve3d/collapse_retry.hpp"
#include "quality/tetrahedron_quality_memo.hpp"
#include "two_and_one_mesh.hpp"

namespace pqmesh::improve3d::detail {
namespace {

using test::two_and_one;

TEST(StarChanges, NothingChangedListsNothing) {
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(two_and_one(), {}, memo);
  StarChanges changes;
  changes.take(mesh);
  std::vector<int> vertices;
  std::vector<std::pair<int, int>> edges;
  changes.since(mesh, vertices, edges);
  EXPECT_TRUE(vertices.empty());
  EXPECT_TRUE(edges.empty());
}

// Moving 3 changes the stars of the vertices of its one tetrahedron (0 1 2 3),
// not those of 4 (whose tetrahedron does not hold 3) nor of the far tetrahedron.
TEST(StarChanges, MovedVertexMarksItsNeighbours) {
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(two_and_one(), {}, memo);
  StarChanges changes;
  changes.take(mesh);
  const int t = 0;
  const double aspect = mesh.aspect(0), dihedral = 0;
  mesh.move_vertex(3, {0.1, 0.1, 1}, {&t, 1}, {&aspect, 1}, {&dihedral, 1});
  std::vector<int> vertices;
  std::vector<std::pair<int, int>> edges;
  changes.since(mesh, vertices, edges);
  EXPECT_EQ(vertices, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(edges.empty());
}

// Replacing the far tetrahedron by a new one on 5 6 7 8 (as a flip would)
// marks the vertices of both and lists the new one's six edges, sorted.
TEST(StarChanges, NewAndDeletedTetrahedraMarkTheirVerticesAndListNewEdges) {
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(two_and_one(), {}, memo);
  StarChanges changes;
  changes.take(mesh);
  mesh.remove_tet(2);
  mesh.add_tet({5, 6, 7, 8}, 0, 3, 70);
  std::vector<int> vertices;
  std::vector<std::pair<int, int>> edges;
  changes.since(mesh, vertices, edges);
  EXPECT_EQ(vertices, (std::vector<int>{5, 6, 7, 8}));
  EXPECT_EQ(edges, (std::vector<std::pair<int, int>>{{5, 6}, {5, 7}, {5, 8}, {6, 7}, {6, 8}, {7, 8}}));
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
