// The length of a face translation (warp.cpp, "Adaptive length";
// docs/algorithm/tet3d_warp.md "Face translations", the case of suite random
// seed 135): the face of an edge box B translated away from B's P edge E takes
// the largest 2^-k (k = 0..4) of (h/8) c n under which its ring points keep
// every exact side decision of §4.3's acceptance rule. Here E runs at a small
// angle to the face and crosses its plane inside B, so beyond that crossing E
// lies outside the face and the full translation would carry a ring segment of
// the face across E's line. The expected fraction is derived by hand below.
#include <gtest/gtest.h>

#include <cmath>
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

// Root cube [0, 1]^3 (h = 1). P: the prism (y in [-1, 2]) over the polygon
// e = (1/64, 1/2), g1 = (1/2, 2), (-2, 2), (-2, -1), f1 = (1/2, -1) (x, z),
// sheared by x -> x - y/16 (planes stay planes). E, the edge at e between
// G (facet 0) and F (facet 4), is the line (1/64 - y/16, y, 1/2): 3.6° off
// face x = 0, crossing its plane at y = 1/4; P holds the side x < E near E.
//  * Box edge l = (0, 0, z) is 1/64 < h/8 from E (E on its +x side); its
//    first-pass direction is cross(E, z) ~ (1, 1/16, 0) oriented away from
//    E: d = -(1, 1/16, 0) / s, s = sqrt(1 + 1/256). Its component on face
//    x = 0's outward normal (-1, 0, 0) is c = 1/s: face x = 0's full
//    translation is (c/8) along -x.
//  * The ring segment [(0, 1, 0), (0, 1, 1)] is crossed by F and G (they
//    meet x = 0, y = 1 at z = 0.5 -/+ 0.145). Its line meets E's line when
//    it is moved 3/64 along -x (E's point at y = 1 is (-3/64, 1, 1/2)), so
//    orient3d(E, segment) changes sign for every move of 3/64 or more:
//    c/8 = 0.1248 and c/16 = 0.0624 do, c/32 = 0.0312 does not.
//  * Every face corner is at least 0.3 from F, G and E before and after the
//    move (the move goes deeper into P, away from F and G), so the
//    clearance conditions hold for every fraction.
// So face x = 0 moves by c/32 along -x: every corner of it has x = -c/32.
TEST(WarpFaceFraction, TranslationStopsShortOfEdgeLine) {
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  Plc3 plc = test::prism_xz({{1.0 / 64, 0.5}, {0.5, 2}, {-2, 2}, {-2, -1}, {0.5, -1}}, -1, 2);
  for (Vec3& v : plc.vertices) v.x -= v.y / 16;
  const Domain3 d = make_domain(plc);
  const int f = 4, g = 0;
  const int edge = edge_between(d, f, g);
  ASSERT_GE(edge, 0);
  const GridPoint c000 = corner_of(t, 0), c010 = corner_of(t, 2), c001 = corner_of(t, 4), c011 = corner_of(t, 6);
  const std::vector<WarpCandidateRecord> cand = {
      {c000, {f, g}, {c001, corner_of(t, 1)}, {}, 0, {{c000, c001}}},
      {c001, {f, g}, {c000, corner_of(t, 5)}, {}, 0, {{c000, c001}}},
      {c010, {f, g}, {c011, corner_of(t, 3)}, {}, 0, {{c010, c011}}},
      {c011, {f, g}, {c010, corner_of(t, 7)}, {}, 0, {{c010, c011}}},
  };
  // The derivation's premise: the full and the half translation flip the
  // segment's side of E's line, the quarter does not.
  const Vec3 a = d.plc.vertices[static_cast<std::size_t>(d.edges[static_cast<std::size_t>(edge)].a)];
  const Vec3 b = d.plc.vertices[static_cast<std::size_t>(d.edges[static_cast<std::size_t>(edge)].b)];
  const double c = 1 / std::sqrt(1 + 1.0 / 256);
  const Vec3 p = grid_coordinates(t, c010), q = grid_coordinates(t, c011);
  const Sign before = orient3d(a, b, p, q);
  ASSERT_NE(before, Sign::Zero);
  for (const double len : {c / 8, c / 16, c / 32}) {
    const Vec3 m{-len, 0, 0};
    EXPECT_EQ(orient3d(a, b, p + m, q + m) == before, len < 3.0 / 64) << len;
  }
  const std::vector<EdgeBoxBounds> boxes = {{corner_of(t, 0), corner_of(t, 7), edge}};
  WarpOptions translated;
  translated.edge_boxes = boxes;
  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(cand), translated);
  for (const GridPoint& pt : {c000, c001, c010, c011}) {
    const Warp* moved = w.find(pt);
    ASSERT_NE(moved, nullptr);
    EXPECT_NEAR(moved->at.x, -c / 32, 1e-12);
  }
  EXPECT_EQ(w.conflicts, 0);
}

}  // namespace
}  // namespace pqmesh::tet3d
