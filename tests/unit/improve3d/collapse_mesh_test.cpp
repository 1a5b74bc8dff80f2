// CollapseMesh's two constructors (src/improve3d/collapse_mesh.hpp): taking
// over the input arrays gives the mesh a copy gives, and empties the input.
#include <gtest/gtest.h>

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
  const CollapseMesh copied(input, facets, memo);
  TetMesh3 moved_input = input;
  std::vector<int> moved_facets = facets;
  CollapseMesh moved(std::move(moved_input), std::move(moved_facets), memo);
  EXPECT_TRUE(moved_input.vertices.empty() && moved_input.tetrahedra.empty() && moved_input.faces.empty());
  EXPECT_TRUE(moved_facets.empty());
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
  copied.write_back(a, fa);
  moved.write_back(b, fb);
  EXPECT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(a.tetrahedra, b.tetrahedra);
  EXPECT_EQ(a.tetrahedron_markers, b.tetrahedron_markers);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.face_markers, b.face_markers);
  EXPECT_EQ(fa, fb);
  EXPECT_EQ(fb, facets);
  std::vector<int> tets;
  moved.tets_of(0, tets);
  EXPECT_EQ(tets, (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
