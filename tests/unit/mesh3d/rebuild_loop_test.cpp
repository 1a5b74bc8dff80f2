// The rebuild loop's partial trials (facet_boxes.cpp, trial_scope.hpp) and
// its tables made from the last one (warp.hpp rewarp_box_vertices) give the
// mesh of full trials and whole tables, vertex for vertex, on every-run seed
// 38 (two or more rebuilds); tet_mesh reports the rebuilds of every-run
// seed 45.
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

TEST(RebuildLoop, PartialTrialsMakeTheMeshOfFullTrials) {
  const Domain3 d = make_domain(test::random_polyhedron(38, test::every_run_polyhedron_options()));
  tet3d::detail::BoxMeshTestHooks full_trials;
  full_trials.partial_trials = false;
  const tet3d::BoxMesh partial = test::warped_box_run(d).mesh;
  const tet3d::BoxMesh full = test::warped_box_run(d, test::warped_options(), full_trials).mesh;
  EXPECT_GE(partial.warp_rebuilds, 2);
  test::expect_same_box_mesh(partial, full);
  EXPECT_LE(test::valid_aspect_times_alpha(d, partial), test::kAspectAlphaC);
}

TEST(RebuildLoop, TablesFromTheLastMakeTheMeshOfWholeTables) {
  const Domain3 d = make_domain(test::random_polyhedron(38, test::every_run_polyhedron_options()));
  tet3d::detail::BoxMeshTestHooks whole_tables;
  whole_tables.incremental_tables = false;
  const tet3d::BoxMesh rewarped = test::warped_box_run(d).mesh;
  const tet3d::BoxMesh whole = test::warped_box_run(d, test::warped_options(), whole_tables).mesh;
  EXPECT_GE(rewarped.warp_rebuilds, 2);
  test::expect_same_box_mesh(rewarped, whole);
  EXPECT_LE(test::valid_aspect_times_alpha(d, rewarped), test::kAspectAlphaC);
}

// The out-of-face table is judged by a partial trial of the jobs it changes
// (facet_boxes.cpp partial_trial_scores_better); full trials judge it by a
// trial of every job. Every-run seed 30: the table is kept; seed
// 100: it loses. Either way the meshes are the same.
TEST(RebuildLoop, PartialTrialsDecideTheOutOfFaceTableAsFullTrials) {
  tet3d::detail::BoxMeshTestHooks full_trials;
  full_trials.partial_trials = false;
  for (const auto& [seed, outcome] : {std::pair<std::uint64_t, std::int64_t>{30, 2}, {100, 1}}) {
    SCOPED_TRACE(seed);
    const Domain3 d = make_domain(test::random_polyhedron(seed, test::every_run_polyhedron_options()));
    const tet3d::BoxMesh partial = test::warped_box_run(d).mesh;
    const tet3d::BoxMesh full = test::warped_box_run(d, test::warped_options(), full_trials).mesh;
    EXPECT_EQ(partial.wider_table, outcome);
    EXPECT_EQ(full.wider_table, outcome);
    test::expect_same_box_mesh(partial, full);
    EXPECT_LE(test::valid_aspect_times_alpha(d, partial), test::kAspectAlphaC);
  }
}

// tet_mesh reports the rebuilds (the CLI summary prints them): every-run
// seed 45 needs one on the thesis's octree (TetSeparation::Always).
TEST(RebuildLoop, TetMeshReportsTheRebuilds) {
  const Domain3 d = make_domain(test::random_polyhedron(45, test::every_run_polyhedron_options()));
  TetMeshOptions thesis_octree;
  thesis_octree.separation = TetSeparation::Always;
  const TetMeshResult r = tet_mesh(d, thesis_octree);
  EXPECT_TRUE(r.stats.warp_failure.empty()) << r.stats.warp_failure;
  EXPECT_EQ(r.stats.warp_rebuilds, 1);
  const CheckReport report = check_mesh(r.mesh, d);
  EXPECT_TRUE(report.valid()) << report.to_text();
}

}  // namespace
}  // namespace pqmesh
