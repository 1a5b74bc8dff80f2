// §4.3 first pass with face translations (warp.hpp `edge_boxes`,
// docs/algorithm/tet3d_warp.md "Face translations", the case of bounded random
// seed 33): for an edge box B whose box edge l is close to B's P edge E, the
// faces of B through l move along their outward normals by the components of
// l's move, so a point of such a face far from E moves too and the face stays
// planar. The expected points are derived by hand below.
#include <gtest/gtest.h>

#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tet3d/warp/warp.hpp"
#include "tree/tree.hpp"
#include "warp_test_util.hpp"

namespace pqmesh::tet3d {
namespace {

// Root cube [0, 1]^3 (h = 1). P: the prism (y in [-1, 2]) over the polygon
// e = (1/64, 1/2), g1 = (1/2, 2), (-2, 2), (-2, -1), f1 = (1/2, -1) (x, z):
// E, the edge at e, is the line (1/64, y, 1/2) between G (facet 0, e -> g1)
// and F (facet 4, f1 -> e); P holds the box's side x < 1/64 near E.
//  * The box edges l1 = (0, 0, z) and l2 = (0, 1, z) are 1/64 < h/8 from E,
//    every other box edge at least 1/2. The first-pass direction for both is
//    cross(E, z) = +x, oriented away from E: d = (-1, 0, 0). Its component on
//    face x = 0's outward normal (-1, 0, 0) is 1, on face y = 0's (or y = 1's)
//    0: only face x = 0 is translated, by h/8 along -x.
//  * Every point of face x = 0 keeps its side of F's and G's planes (they
//    cross x = 0 at z = 0.548 and 0.452 only on their extensions beyond E,
//    and the move goes deeper into P); the segments along x keep their lines;
//    the segments along z on x = 0 stay on E's -x side.
//  * So the four corners of face x = 0 and its point m = (0, 1/2, 0) go to
//    x = -1/8 exactly. Without the edge box, m (on the box edge (x = 0,
//    z = 0), 1/2 from E; 0.168 from F and G) is not moved at all.
TEST(WarpFaceShift, EdgeBoxFaceThroughACloseBoxEdgeIsTranslated) {
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const Domain3 d = make_domain(test::prism_xz({{1.0 / 64, 0.5}, {0.5, 2}, {-2, 2}, {-2, -1}, {0.5, -1}}, -1, 2));
  const int f = 4, g = 0;
  const int edge = edge_between(d, f, g);
  ASSERT_GE(edge, 0);
  const GridPoint c000 = corner_of(t, 0), c010 = corner_of(t, 2), c001 = corner_of(t, 4), c011 = corner_of(t, 6);
  GridPoint m = c000;
  m.f[1] += t.key(0).fine_side() / 2;
  const std::vector<WarpCandidateRecord> cand = {
      {c000, {f, g}, {c001, corner_of(t, 1), m}, {}, 0, {{c000, c001}}},
      {c001, {f, g}, {c000, corner_of(t, 5), c011}, {}, 0, {{c000, c001}}},
      {c010, {f, g}, {c011, corner_of(t, 3), m}, {}, 0, {{c010, c011}}},
      {c011, {f, g}, {c010, corner_of(t, 7), c001}, {}, 0, {{c010, c011}}},
      {m, {f, g}, {c000, c010}, {}, 0, {}},
  };
  const WarpTable plain = warp_box_vertices(t, corners, d, make_warp_candidates(cand));
  EXPECT_EQ(plain.find(m), nullptr);
  const std::vector<EdgeBoxBounds> boxes = {{corner_of(t, 0), corner_of(t, 7), edge}};
  WarpOptions translated;
  translated.edge_boxes = boxes;
  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(cand), translated);
  for (const GridPoint& p : {c000, c001, c010, c011, m}) {
    const Warp* moved = w.find(p);
    ASSERT_NE(moved, nullptr);
    const Vec3 x0 = grid_coordinates(t, p);
    EXPECT_EQ(moved->at.x, -1.0 / 8);
    EXPECT_EQ(moved->at.y, x0.y);
    EXPECT_EQ(moved->at.z, x0.z);
  }
  EXPECT_EQ(w.conflicts, 0);
}

}  // namespace
}  // namespace pqmesh::tet3d
