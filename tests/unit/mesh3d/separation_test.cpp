// TetSeparation (pqmesh/tetmesh.hpp): the light octree (no separating splits
// of §4.1.7 steps 6 and 9) is meshed first and kept when valid and within the
// aspect bound; otherwise octrees separated near the faces above the bound,
// then the thesis's octree. Every mesh here
// passes check_mesh and the bound C / alpha.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "aspect_alpha_property.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/flat_edge_domains.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

TetMeshOptions with(TetSeparation separation) {
  TetMeshOptions o;
  o.separation = separation;
  return o;
}

// Valid, within C / alpha; returns aspect * alpha.
double expect_valid_and_bounded(const std::string& what, const Domain3& d, const TetMeshResult& r) {
  const CheckReport report = check_mesh(r.mesh, d);
  EXPECT_TRUE(report.valid()) << what << ": " << report.to_text();
  const double product = test::aspect_times_alpha(quality_report(r.mesh).aspect_ratio.max, compute_alpha(d.plc).radians);
  EXPECT_LE(product, test::kAspectAlphaC) << what;
  return product;
}

Domain3 corpus(const char* name) {
  return make_domain(read_plc(test::data_path(std::string("3d/") + name)));
}

// On models the light octree meshes within the bound, the default keeps its
// mesh (no separating split) and it has fewer tetrahedra than the thesis's.
class LightKept : public ::testing::TestWithParam<const char*> {};

TEST_P(LightKept, FewerTetrahedraThanTheThesisOctree) {
  const Domain3 d = corpus(GetParam());
  const TetMeshResult light = tet_mesh(d);
  const TetMeshResult thesis = tet_mesh(d, with(TetSeparation::Always));
  EXPECT_FALSE(light.stats.separated) << light.stats.light_rejected;
  EXPECT_TRUE(light.stats.light_rejected.empty());
  EXPECT_TRUE(thesis.stats.separated);
  EXPECT_TRUE(thesis.stats.light_rejected.empty());  // never tried
  expect_valid_and_bounded(GetParam(), d, light);
  expect_valid_and_bounded(GetParam(), d, thesis);
  EXPECT_LT(light.mesh.tetrahedra.size(), thesis.mesh.tetrahedra.size());
  std::printf("%-18s light %8zu tets, thesis octree %9zu tets\n", GetParam(), light.mesh.tetrahedra.size(),
              thesis.mesh.tetrahedra.size());
}

INSTANTIATE_TEST_SUITE_P(Corpus, LightKept, ::testing::Values("cube.poly", "l_block.poly", "schoenhardt.poly"));

// Every-run seed 4 with every facet triangle its own facet (alpha 2.63 deg):
// the light octree's worst tetrahedron is above C / alpha; the octree
// separated near the faces of its leaf meets the bound with fewer
// tetrahedra than the thesis's octree.
TEST(SeparationFallback, FlatSeed4SeparatesNearTheWorstLeaf) {
  const Domain3 d = test::every_run_seed_as_triangles(4);
  const TetMeshResult r = tet_mesh(d);
  EXPECT_FALSE(r.stats.separated);
  EXPECT_GT(r.stats.separated_faces, 0);
  EXPECT_NE(r.stats.light_rejected.find("above C / alpha"), std::string::npos) << r.stats.light_rejected;
  EXPECT_GT(r.stats.seconds_light, 0);
  const double product = expect_valid_and_bounded("flat seed 4", d, r);
  const TetMeshResult thesis = tet_mesh(d, with(TetSeparation::Always));
  expect_valid_and_bounded("flat seed 4, thesis octree", d, thesis);
  EXPECT_LT(r.mesh.tetrahedra.size(), thesis.mesh.tetrahedra.size());
  std::printf("flat seed 4: %zu tets separated near %lld faces (thesis octree %zu), aspect * alpha %.1f; "
              "light dropped: %s\n",
              r.mesh.tetrahedra.size(), static_cast<long long>(r.stats.separated_faces), thesis.mesh.tetrahedra.size(),
              product, r.stats.light_rejected.c_str());
}

}  // namespace
}  // namespace pqmesh
