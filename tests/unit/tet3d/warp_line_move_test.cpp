// §4.3 warping (warp.hpp): a box vertex near F whose every move along F's
// normal is refused is moved along one of its ring segments' lines instead
// (docs/algorithm/tet3d_warp.md "Moves along a ring segment's line"; the case
// of bounded random seed 58). The expected point is derived by hand below.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "predicates/predicates.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tet3d/warp/warp.hpp"
#include "tree/tree.hpp"
#include "warp_test_util.hpp"

namespace pqmesh::tet3d {
namespace {

TEST(WarpLineMove, CornerNearFMovesAlongItsCrossedSegment) {
  // Root cube [0, 1]^3, h = 1; v = (0, 0, 0) with ring neighbours (1, 0, 0),
  // (0, 1, 0), (0, 0, 1). P: the prism (y in [-1, 2]) over the polygon e =
  // (9/64, 1/64), g1 = (1/2, 2), (-2, 2), (-2, -1), f1 = (-1, -1/8) (x, z).
  // F (facet 4, f1 -> e) has slope 9/73 and passes z = -8/4672 below v, so
  // v is 0.0017 < h/16 from F (and above it); G (facet 0, e -> g1) is 0.136
  // from v. E, their edge, is the line (9/64, y, 1/64): 1/64 above the ring
  // segment s = [v, (1, 0, 0)], which F and G both cross.
  //  * First pass: s is 1/64 < h/8 from E: v moves h/8 along -z, across
  //    F's plane: refused (side rule).
  //  * Second pass alone: h/16 along F's normal (up, slightly -x): s's line
  //    then passes above E (at x = 9/64 it is at z = 0.053 > 1/64), so the
  //    side of E's line that s passes changes: refused (crossing rule).
  //  * Its fractions 1/2 .. 1/16 keep that side but bring s nearer E (the
  //    clearance 1/64 / (h/8) falls): refused ("none may decrease").
  //  * Along s's own line, away from (1, 0, 0): v' = (-1/16, 0, 0). s's line
  //    is unchanged (orient3d(E, v', w) keeps its sign exactly), F is
  //    0.0017 + (1/16) sin(atan(9/73)) = 0.0093 away (clearance 0.149 from
  //    0.027), E stays 1/64 from s (0.125); the smallest clearance grows
  //    from 0.027 to 0.125. Half of it gives only 0.088 for F; the lines of
  //    the other segments: along -y keeps every distance, along -z crosses F.
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const Domain3 d = make_domain(test::prism_xz({{9.0 / 64, 1.0 / 64}, {0.5, 2}, {-2, 2}, {-2, -1}, {-1, -1.0 / 8}}, -1, 2));
  const int f = 4, g = 0;
  const GridPoint v = corner_of(t, 0), wx = corner_of(t, 1);
  const std::vector<WarpCandidateRecord> cand = {{v, {f, g}, {wx, corner_of(t, 2), corner_of(t, 4)}, {}, 0, {}}};
  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(cand));
  const Warp* moved = w.find(v);
  ASSERT_NE(moved, nullptr);
  EXPECT_EQ(moved->at.x, -1.0 / 16);
  EXPECT_EQ(moved->at.y, 0.0);
  EXPECT_EQ(moved->at.z, 0.0);
  EXPECT_EQ(w.shortened, 1);
  EXPECT_EQ(w.conflicts, 0);
  EXPECT_EQ(w.fallback, 0);
  // The exact decisions the move must keep: v's side of F and G, and the
  // side of E's line that the crossed segment s passes.
  const Vec3 a{9.0 / 64, -1, 1.0 / 64}, b{9.0 / 64, 2, 1.0 / 64}, x1{1, 0, 0}, x0{0, 0, 0};
  EXPECT_EQ(orient3d(a, b, moved->at, x1), orient3d(a, b, x0, x1));
  EXPECT_NE(orient3d(a, b, x0, x1), Sign::Zero);
}

}  // namespace
}  // namespace pqmesh::tet3d
