// Out-of-face moves of reported points, decided once per shared face
// (facet_boxes.cpp mesh_boxes, WarpOptions::out_of_face), through tet_mesh's
// pipeline and check_mesh. Every-run seed 30 (the move improves the edge
// box): aspect x alpha <= 850. Every-run seed 100 (the move would bend the
// face of the box across): aspect x alpha <= 452.
#include <gtest/gtest.h>

#include <cstdint>

#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"
#include "warped_box_mesh.hpp"

namespace pqmesh {
namespace {

double every_run_aspect_times_alpha(std::uint64_t seed) {
  const Domain3 d = make_domain(test::random_polyhedron(seed, test::every_run_polyhedron_options()));
  return test::valid_aspect_times_alpha(d, test::warped_box_mesh(d));
}

TEST(SharedFace, ReportedPointMovesOutOfTheEdgeBoxWhenTheMeshImproves) {
  EXPECT_LE(every_run_aspect_times_alpha(30), 850.0);
}

TEST(SharedFace, OutOfFaceMoveIsRejectedWhenTheBoxAcrossGetsWorse) {
  EXPECT_LE(every_run_aspect_times_alpha(100), 452.0);
}

}  // namespace
}  // namespace pqmesh
