// ImprovingCollapses (src/improve3d/improving_collapse.hpp) on a hand-made
// star: the octahedron with vertices +-e_i (input vertices) split into eight
// tetrahedra around an interior vertex u near the face (e_1, e_2, e_3), so
// the tetrahedron on that face is flat (below the work threshold). The pass
// collapses u onto a vertex of that tetrahedron: four tetrahedra are left,
// each positive, none with a minimum dihedral angle below the old star's
// least, and a second pass finds nothing below the threshold to remove.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "improve3d/collapse_check.hpp"
#include "improve_support.hpp"
#include "improve3d/collapse_mesh.hpp"
#include "improve3d/improving_collapse.hpp"
#include "improve3d/size_bound.hpp"
#include "improve3d/smooth.hpp"
#include "improve3d/vertex_classes.hpp"
#include "predicates/predicates.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::improve3d::detail {
namespace {

constexpr int kU = 6;

TEST(ImprovingCollapses, RemovesTheFlatTetrahedronWithoutLoweringTheLeastAngle) {
  const TetMesh3 m = test::octahedron_star({1, 0, 0}, {0.3, 0.3, 0.3});
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(m, {}, memo);
  double old_least = 180;
  for (int t = 0; t < mesh.tet_count(); ++t) old_least = std::min(old_least, mesh.dihedral(t));
  ASSERT_LT(old_least, kWorkBelowDihedral);  // the flat tetrahedron is visited
  VertexClasses classes;
  classes.kind.assign(7, VertexClass::Input);
  classes.kind[kU] = VertexClass::Interior;
  classes.begin.assign(8, 0);
  const std::vector<Vec3> no_points;  // SizeBound keeps references
  const std::vector<double> no_sizes;
  const SizeBound size(0, no_points, no_sizes);
  Collapser collapser(mesh, classes, size, {1e9, 1e9, 180}, memo);
  ImprovingCollapses improving(mesh, classes, collapser);
  EXPECT_EQ(improving.pass(), 1);
  EXPECT_FALSE(mesh.vertex_alive(kU));
  EXPECT_EQ(mesh.live_tets(), 4);
  for (int t = 0; t < mesh.tet_count(); ++t) {
    const auto& k = mesh.tet(t);
    if (k[0] < 0) continue;
    EXPECT_EQ(orient3d(mesh.point(k[0]), mesh.point(k[1]), mesh.point(k[2]), mesh.point(k[3])), Sign::Positive);
    EXPECT_GE(mesh.dihedral(t), old_least);
    EXPECT_GE(mesh.dihedral(t), kWorkBelowDihedral);
  }
  EXPECT_EQ(improving.pass(), 0);
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
