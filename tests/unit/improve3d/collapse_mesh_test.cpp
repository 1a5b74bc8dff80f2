// CollapseMesh's two constructors (src/improve3d/collapse_mesh.hpp): taking
// over the input arrays gives the mesh a copy gives, and empties the input.
#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "quality/tetrahedron_quality_memo.hpp"
#include "two_and_one_mesh.hpp"

namespace pqmesh::improve3d::detail {
namespace {

TEST(CollapseMesh, TakingTheArraysEqualsCopyingThem) {
  TetMesh3 input = test::two_and_one();
  input.faces = {{0, 1, 3}, {5, 6, 7}};
  input.face_markers = {4, 9};
  input.tetrahedron_markers = {1, 1, 2};
  const std::vector<int> facets = {2, 5};
  TetrahedronQualityMemo memo;
  CollapseMesh copied(input, facets, memo);
  TetMesh3 moved_input = input;
  std::vector<int> moved_facets = facets;
  CollapseMesh moved(std::move(moved_input), std::move(moved_facets), memo);
  EXPECT_TRUE(moved_input.vertices.empty() && moved_input.tetrahedra.empty() && moved_input.faces.empty());
  EXPECT_TRUE(moved_facets.empty());
  std::vector<int> tets;
  moved.tets_of(0, tets);
  EXPECT_EQ(tets, (std::vector<int>{0, 1}));
  ASSERT_EQ(moved.vertex_count(), copied.vertex_count());
  ASSERT_EQ(moved.tet_count(), copied.tet_count());
  for (int t = 0; t < copied.tet_count(); ++t) {
    EXPECT_EQ(moved.tet(t), copied.tet(t));
    EXPECT_EQ(moved.tet_marker(t), copied.tet_marker(t));
    EXPECT_EQ(moved.aspect(t), copied.aspect(t));
    EXPECT_EQ(moved.dihedral(t), copied.dihedral(t));
  }
  EXPECT_FALSE(moved.one_region());
  TetMesh3 a, b;
  std::vector<int> fa, fb;
  std::move(copied).write_back(a, fa);
  std::move(moved).write_back(b, fb);
  EXPECT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(a.tetrahedra, b.tetrahedra);
  EXPECT_EQ(a.tetrahedron_markers, b.tetrahedron_markers);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.face_markers, b.face_markers);
  EXPECT_EQ(fa, fb);
  EXPECT_EQ(fb, facets);
}

// One region: every tetrahedron reads the one marker; a tetrahedron added
// with another marker makes two regions, and compacting and writing back
// keep each tetrahedron's marker.
TEST(CollapseMesh, MarkersOfOneRegionAndThenTwo) {
  TetMesh3 input = test::two_and_one();
  input.tetrahedron_markers = {3, 3, 3};
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(std::move(input), std::vector<int>{}, memo);
  EXPECT_TRUE(mesh.one_region());
  EXPECT_EQ(mesh.tet_marker(2), 3);
  const int same = mesh.add_tet({5, 6, 8, 7}, 3, 1.5, 60.0);
  EXPECT_TRUE(mesh.one_region());
  const int other = mesh.add_tet({5, 6, 7, 8}, 5, 1.5, 60.0);
  EXPECT_FALSE(mesh.one_region());
  EXPECT_EQ(mesh.tet_marker(same), 3);
  EXPECT_EQ(mesh.tet_marker(other), 5);
  EXPECT_EQ(mesh.tet_marker(1), 3);
  mesh.remove_tet(0);
  mesh.compact_tets();  // ids 1 2 3 4 become 0 1 2 3
  EXPECT_EQ(mesh.tet_marker(3), 5);
  TetMesh3 out;
  std::vector<int> facets;
  std::move(mesh).write_back(out, facets);
  EXPECT_EQ(out.tetrahedron_markers, (std::vector<int>{3, 3, 3, 5}));
  ASSERT_EQ(out.tetrahedra.size(), 4U);
  EXPECT_EQ(out.tetrahedra[3], (std::array<int, 4>{5, 6, 7, 8}));
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
