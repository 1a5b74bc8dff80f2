// The minimum dihedral rule of Collapser::quality_allows
// (src/improve3d/collapse_check.hpp, ImproveOptions::min_dihedral): with the
// rule at D, a collapse is refused when a moved tetrahedron's minimum
// dihedral angle would fall below min(D, the least of the old region), and
// allowed otherwise; without it (D = 0) only the aspect limits apply.
//
// The mesh: an octahedron with vertices v, -e_1, +-e_2, +-e_3 (input
// vertices) split into eight tetrahedra around an interior vertex u.
// Collapsing u onto v leaves the four tetrahedra around the diagonal
// (v, -e_1), whose minimum dihedral angle `fan` the test measures; with v
// pulled out to (1.5, 0.9, 0.9) and u at the centre the old region's least
// angle exceeds `fan`; with v = e_1 and u near a face it is below it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "improve3d/collapse_check.hpp"
#include "improve_support.hpp"
#include "improve3d/collapse_mesh.hpp"
#include "improve3d/size_bound.hpp"
#include "improve3d/vertex_classes.hpp"
#include "pqmesh/quality.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::improve3d::detail {
namespace {

constexpr int kU = 6, kV = 0;  // u interior, v an input vertex

// Six input vertices, u interior, no boundary triangles.
VertexClasses classes() {
  VertexClasses c;
  c.kind.assign(7, VertexClass::Input);
  c.kind[kU] = VertexClass::Interior;
  c.begin.assign(8, 0);
  return c;
}

double least_dihedral(const TetMesh3& m, const std::vector<std::array<int, 4>>& tets) {
  double least = 180;
  for (const auto& k : tets) {
    const auto p = [&](int i) { return m.vertices[static_cast<std::size_t>(k[static_cast<std::size_t>(i)])]; };
    least = std::min(least, tetrahedron_quality(p(0), p(1), p(2), p(3)).min_dihedral_deg);
  }
  return least;
}

// The tetrahedra left after u goes to v: those of the star not holding v, with u replaced by v.
std::vector<std::array<int, 4>> moved(const TetMesh3& m) {
  std::vector<std::array<int, 4>> out;
  for (auto k : m.tetrahedra) {
    if (std::find(k.begin(), k.end(), kV) != k.end()) continue;
    std::replace(k.begin(), k.end(), kU, kV);
    out.push_back(k);
  }
  return out;
}

bool collapses(const TetMesh3& m, double min_dihedral) {
  TetrahedronQualityMemo memo;
  CollapseMesh mesh(m, {}, memo);
  const VertexClasses c = classes();
  const std::vector<Vec3> no_points;  // SizeBound keeps references
  const std::vector<double> no_sizes;
  const SizeBound size(0, no_points, no_sizes);
  // Aspect limits far above every tetrahedron here: only the dihedral rule can refuse.
  Collapser collapser(mesh, c, size, {1e9, 1e9, min_dihedral}, memo);
  return collapser.try_collapse(kU, kV);
}

TEST(CollapseMinDihedral, RefusesBelowTheRuleAndTheRegionsLeast) {
  const TetMesh3 m = test::octahedron_star({1.5, 0.9, 0.9}, {0, 0, 0});  // v pulled out: a flat fan tetrahedron
  const double fan = least_dihedral(m, moved(m)), old_least = least_dihedral(m, m.tetrahedra);
  ASSERT_LT(fan + 1, old_least);  // the collapse lowers the region's least angle
  EXPECT_TRUE(collapses(m, 0));
  EXPECT_TRUE(collapses(m, fan - 1));
  EXPECT_FALSE(collapses(m, fan + 1));
  EXPECT_FALSE(collapses(m, old_least));
}

TEST(CollapseMinDihedral, AllowsWhatKeepsTheRegionsLeast) {
  const TetMesh3 m = test::octahedron_star({1, 0, 0}, {0.3, 0.3, 0.3});  // near face (e_1, e_2, e_3): a flat old tetrahedron
  const double fan = least_dihedral(m, moved(m)), old_least = least_dihedral(m, m.tetrahedra);
  ASSERT_LT(old_least, fan);  // min(D, old_least) = old_least for every D above it
  EXPECT_TRUE(collapses(m, 0));
  EXPECT_TRUE(collapses(m, 90));
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
