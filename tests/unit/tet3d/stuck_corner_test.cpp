// Stuck corners (tet3d/rebuild/stuck_corners.hpp; docs/algorithm/mesh3d.md
// "Light construction first"): a ring point near F whose every move the side
// rules or the clearance test refuse stays in place and is listed by
// stuck_points; one with a shortened move is not. The configurations are
// derived by hand below.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tet3d/rebuild/stuck_corners.hpp"
#include "tet3d/warp/warp.hpp"
#include "tree/tree.hpp"
#include "warp_test_util.hpp"

namespace pqmesh::tet3d {
namespace {

// Root cube [0, 1]^3, h = 1; v = (0, 0, 0) with ring neighbours (1, 0, 0),
// (0, 1, 0), (0, 0, 1). P: the prism (y in [-1, 2]) under a roof with a
// reflex kink at E = (-1/2, zE) (x, z): F (facet 1) rises from E to the
// right with slope sF = 2^-10 and passes 2^-20 above v; G (facet 2) rises
// from the left to E with slope sG, chosen so that G's plane, extended to
// x = 0, passes `below` under v: zE + sG / 2 = -below. So v lies inside P
// (under F) and beyond G's plane, between the two planes. E is 1/2 from
// every ring segment of v (no first pass); F is 2^-20 < h/16 from v, G's
// facet 1/2 (only F is close).
Domain3 kinked_roof(double below) {
  const double zE = std::ldexp(1.0, -20) - std::ldexp(1.0, -11);  // F at x = 0: zE + sF / 2 = 2^-20
  const double sF = std::ldexp(1.0, -10), sG = 2 * (-below - zE);
  const double zR = zE + sF * 2.5, zL = zE - sG * 1.5;
  return make_domain(test::prism_xz({{2, -2}, {2, zR}, {-0.5, zE}, {-2, zL}, {-2, -2}}, -1, 2));
}

// v's table entry and its journal's stuck points, v a candidate with facets
// F and G.
struct Warped {
  WarpTable table;
  std::vector<GridPoint> stuck;
};

Warped warp_v(const OctTree& t, const Domain3& d) {
  const CornerSet corners(t, t.leaves());
  const GridPoint v = corner_of(t, 0);
  const std::vector<WarpCandidateRecord> cand = {{v, {1, 2}, {corner_of(t, 1), corner_of(t, 2), corner_of(t, 4)}, {}, 0, {}}};
  const WarpCandidates candidates = make_warp_candidates(cand);
  WarpJournal journal;
  Warped out{warp_box_vertices(t, corners, d, candidates, {}, &journal), {}};
  out.stuck = stuck_points(candidates, journal);
  return out;
}

TEST(StuckCorners, CornerBetweenTwoNearlyCoplanarPlanesIsStuck) {
  // G's plane 2^-20 under v. Every move v may make:
  //  * h/16 along -n_F (down, away from F) and its fractions down to h/256:
  //    each goes more than 2^-20 down, across G's plane (side rule);
  //  * along -x by h/16 .. h/256: F's plane at x = -dx is 2^-20 - 2^-10 dx
  //    above v's height, below it for dx >= 2^-8 (side rule);
  //  * along -z: across G's plane, as the first;
  //  * along -y: both planes contain the y axis (sides kept), but the
  //    prism's facets run along y, so no distance grows (clearance rule).
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const Domain3 d = kinked_roof(std::ldexp(1.0, -20));
  const Warped w = warp_v(t, d);
  EXPECT_EQ(w.table.find(corner_of(t, 0)), nullptr);
  EXPECT_EQ(w.table.conflicts, 1);
  ASSERT_EQ(w.stuck.size(), 1u);
  EXPECT_EQ(w.stuck[0], corner_of(t, 0));
}

TEST(StuckCorners, CornerWithRoomForAShortenedMoveIsNotStuck) {
  // G's plane 2^-6 under v: h/16 and h/32 down cross it; shorter moves down
  // stay above it and take v farther from F (from 2^-20): a shortened move.
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const Domain3 d = kinked_roof(std::ldexp(1.0, -6));
  const Warped w = warp_v(t, d);
  EXPECT_NE(w.table.find(corner_of(t, 0)), nullptr);
  EXPECT_EQ(w.table.conflicts, 0);
  EXPECT_EQ(w.table.shortened, 1);
  EXPECT_TRUE(w.stuck.empty());
}

}  // namespace
}  // namespace pqmesh::tet3d
