// The worst-box freeze (tet3d/rebuild/worst_box_freeze.hpp): flat-edge seeds 100
// and 49 (every facet triangle its own facet) are above C without it and
// within C with it; every-run seed 45, below the threshold, keeps its mesh.
// Every mesh here passes check_mesh.
#include <gtest/gtest.h>

#include <cstdio>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/flat_edge_domains.hpp"
#include "support/random_domains.hpp"
#include "tet3d/rebuild/worst_box_freeze.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

tet3d::detail::BoxMeshTestHooks without_freeze() {
  tet3d::detail::BoxMeshTestHooks hooks;
  hooks.freeze_worst_box = false;
  return hooks;
}

TEST(WorstBoxFreeze, BringsFlatSeed100WithinTheConstant) {
  const Domain3 d = test::every_run_seed_as_triangles(100);
  const tet3d::BoxMesh before = test::warped_box_run(d, test::warped_options(), without_freeze()).mesh;
  const double before_product = test::valid_aspect_times_alpha(d, before);
  EXPECT_EQ(before.worst_box_rounds, 0);
  // The input this pass exists for: above C without it.
  EXPECT_GT(before_product, test::kAspectAlphaC);

  const tet3d::BoxMesh after = test::warped_box_run(d).mesh;
  const double after_product = test::valid_aspect_times_alpha(d, after);
  EXPECT_GE(after.worst_box_rounds, 1);
  EXPECT_LE(after.worst_box_rounds, tet3d::kWorstBoxRounds);
  EXPECT_LT(after_product, before_product);
  EXPECT_LE(after_product, test::kAspectAlphaC);
  std::printf("flat seed 100: aspect * alpha %.1f -> %.1f in %lld rounds\n", before_product, after_product,
              static_cast<long long>(after.worst_box_rounds));
  // The rebuild loop's work is the same; the freeze only adds frozen points.
  EXPECT_EQ(after.warp_rebuilds, before.warp_rebuilds);
  EXPECT_GT(after.warp_inverting_left, before.warp_inverting_left);
}

// Through tet_mesh, with the boundary and its markers: flat seed 49 on the
// thesis's octree (TetSeparation::Always).
TEST(WorstBoxFreeze, TetMeshReportsTheRoundsOnFlatSeed49) {
  const Domain3 d = test::every_run_seed_as_triangles(49);
  TetMeshOptions thesis_octree;
  thesis_octree.separation = TetSeparation::Always;
  const TetMeshResult r = tet_mesh(d, thesis_octree);
  EXPECT_TRUE(r.stats.warp_failure.empty()) << r.stats.warp_failure;
  EXPECT_GE(r.stats.worst_box_rounds, 1);
  const CheckReport report = check_mesh(r.mesh, d);
  EXPECT_TRUE(report.valid()) << report.to_text();
  const double product =
      test::aspect_times_alpha(quality_report(r.mesh).aspect_ratio.max, compute_alpha(d.plc).radians);
  EXPECT_LE(product, test::kAspectAlphaC);
  std::printf("flat seed 49: %zu tets, aspect * alpha %.1f after %lld rounds\n", r.mesh.tetrahedra.size(), product,
              static_cast<long long>(r.stats.worst_box_rounds));
}

// Every-run seed 45 (the every-run family's worst, aspect ratio x alpha 990)
// stays below the threshold: the same mesh, byte for byte, with the pass on.
TEST(WorstBoxFreeze, LeavesARunBelowTheThresholdAlone) {
  const Domain3 d = make_domain(test::random_polyhedron(45, test::every_run_polyhedron_options()));
  const tet3d::BoxMesh on = test::warped_box_run(d).mesh;
  const tet3d::BoxMesh off = test::warped_box_run(d, test::warped_options(), without_freeze()).mesh;
  EXPECT_EQ(on.worst_box_rounds, 0);
  ASSERT_EQ(on.mesh.vertices.size(), off.mesh.vertices.size());
  for (std::size_t i = 0; i < on.mesh.vertices.size(); ++i)
    ASSERT_EQ(on.mesh.vertices[i], off.mesh.vertices[i]) << "vertex " << i;
  EXPECT_EQ(on.mesh.tetrahedra, off.mesh.tetrahedra);
  EXPECT_LE(test::valid_aspect_times_alpha(d, on), test::kAspectAlphaC);
}

}  // namespace
}  // namespace pqmesh
