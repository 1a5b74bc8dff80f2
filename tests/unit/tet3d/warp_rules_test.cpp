// Warping rules of tet3d that the thesis leaves open
// (docs/algorithm/tet3d_warp.md), and §4.3's first pass on whole box edges: a
// face square's centre is carried with its corners (warp.hpp), a move refused
// because it would cross another facet's plane is shortened (warp.hpp), and a P
// edge crosses a square whose corners moved where it meets their mean plane
// (warped_crossing.hpp). Expected points are derived by hand from the
// configuration (the warped squares below are planar quadrilaterals, so the
// crossing is a line-plane intersection computed here independently).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "predicates/predicates.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/points/grid_point.hpp"
#include "tet3d/warp/warp.hpp"
#include "tet3d/squares/warped_crossing.hpp"
#include "tree/tree.hpp"
#include "warp_test_util.hpp"

namespace pqmesh::tet3d {
namespace {

// The root's lower z face (one square: the root has no children).
FaceSquare bottom_square(const OctTree& t, const CornerSet& corners) {
  std::vector<FaceSquare> s;
  face_squares(t.key(0), 2, false, corners, s);
  EXPECT_EQ(s.size(), 1u);
  return s.at(0);
}

// Candidates: the four corners of the bottom face (ring neighbours along the
// square) with every facet, and the square's centre.
std::vector<WarpCandidateRecord> bottom_candidates(const OctTree& t, const FaceSquare& s, int facets) {
  std::vector<int> all;
  for (int f = 0; f < facets; ++f) all.push_back(f);
  const GridPoint c[4] = {corner_of(t, 0), corner_of(t, 1), corner_of(t, 3), corner_of(t, 2)};  // around the face
  std::vector<WarpCandidateRecord> out;
  for (int i = 0; i < 4; ++i) out.push_back({c[i], all, {c[(i + 1) % 4], c[(i + 3) % 4]}, {}, 0, {}});
  out.push_back({s.centre(), all, {}, {c[0], c[1], c[2], c[3]}, -1, {}});
  return out;
}

TEST(WarpRules, SquareCentreMovesWithItsCorners) {
  // P = [-1, 2]^2 x [0.01, 2]; the root cube [0, 1]^3 (h = 1). Each bottom
  // corner is 0.01 <= h/16 below the bottom facet and far from every P edge:
  // the second pass moves it h/16 along -z. The centre (0.5, 0.5, 0) moves
  // by the mean of the four equal moves and stays below the facet.
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const Domain3 d = make_domain(test::box({-1, -1, 0.01}, {2, 2, 2}));
  const FaceSquare s = bottom_square(t, corners);
  const std::vector<WarpCandidateRecord> cand = bottom_candidates(t, s, 6);
  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(cand));
  for (int i = 0; i < 4; ++i) {
    const Warp* c = w.find(cand[static_cast<std::size_t>(i)].p);
    ASSERT_NE(c, nullptr) << "corner " << i;
    EXPECT_EQ(c->at.z, -1.0 / 16);
  }
  const Warp* c = w.find(s.centre());
  ASSERT_NE(c, nullptr);
  EXPECT_DOUBLE_EQ(c->at.x, 0.5);
  EXPECT_DOUBLE_EQ(c->at.y, 0.5);
  EXPECT_DOUBLE_EQ(c->at.z, -1.0 / 16);
  EXPECT_EQ(w.centres, 1);
}

TEST(WarpRules, SquareCentreOnAFacetPlaneStays) {
  // P = [0.5, 2] x [-1, 2] x [0.01, 2]: the corners at x = 1 are close to
  // the bottom facet and move; the centre lies exactly on the plane x = 0.5
  // of a facet, an exact boundary point: it is not moved.
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const Domain3 d = make_domain(test::box({0.5, -1, 0.01}, {2, 2, 2}));
  const FaceSquare s = bottom_square(t, corners);
  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(bottom_candidates(t, s, 6)));
  EXPECT_NE(w.find(corner_of(t, 1)), nullptr);
  EXPECT_EQ(w.find(s.centre()), nullptr);
  EXPECT_EQ(w.centres, 0);
}

// The facet of d containing x (distance 0).
int facet_at(const Domain3& d, Vec3 x) {
  for (int f = 0; f < static_cast<int>(d.plc.facets.size()); ++f)
    if (facet_distance(d, f, x) == 0) return f;
  return -1;
}

TEST(WarpRules, RefusedMoveIsShortened) {
  // P: a step, [-1, 5] x [-1, 2] x [-2, 0.01] joined to [5, 6] x [-1, 2] x
  // [-2, -0.03]. The box vertex v = (0, 0, 0) (root cube [0, 1]^3, h = 1)
  // uses the top facet F (z = 0.01, 0.01 < h/16 above v) and the lower top
  // facet G (z = -0.03, 5 away: not close, but its plane is 0.03 below v).
  // The second pass moves v h/16 along -z, across G's plane: refused (v's
  // side of G decides its squares). No first pass (F and G share no edge).
  // Shortened moves to z = -1/32, -1/64, -1/128, -1/256: the first crosses
  // G's plane too; of the others the farthest from F is z = -1/64
  // (clearance (0.01 + 1/64) / (1/16) = 0.41, against 0.16 unmoved).
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const Domain3 d = make_domain(test::prism_xz({{-1, -2}, {6, -2}, {6, -0.03}, {5, -0.03}, {5, 0.01}, {-1, 0.01}}, -1, 2));
  const int f = facet_at(d, {0, 0.5, 0.01}), g = facet_at(d, {5.5, 0.5, -0.03});
  ASSERT_GE(f, 0);
  ASSERT_GE(g, 0);
  const std::vector<WarpCandidateRecord> cand = {
      {corner_of(t, 0), {f, g}, {corner_of(t, 1), corner_of(t, 2)}, {}, 0, {}}};
  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(cand));
  const Warp* v = w.find(corner_of(t, 0));
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->at.x, 0.0);
  EXPECT_EQ(v->at.y, 0.0);
  EXPECT_EQ(v->at.z, -1.0 / 64);
  EXPECT_EQ(w.shortened, 1);
  EXPECT_EQ(w.conflicts, 0);
  EXPECT_EQ(w.fallback, 0);
}

TEST(WarpRules, EdgeCrossingMovesOntoTheWarpedSquare) {
  // E runs along (0, -1, 1) in the plane x = 0.5 and crosses the bottom face
  // z = 0 at y = 0.02, 0.02 from the root's box edge y = z = 0: it clips the
  // cube near that edge. The first pass moves the edge by h/8 away from E,
  // along (0, -1, -1)/sqrt(2): corners 0 and 1 to y = z = -a, a = 1/(8
  // sqrt(2)). The warped bottom square is planar (two edges parallel to x),
  // through the lines (y, z) = (-a, -a) and (1, 0): z = a (y - 1) / (1 + a).
  // With y + z = 0.02 on E: y = (0.02 (1 + a) + a) / (1 + 2a).
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const FaceSquare s = bottom_square(t, corners);
  const Vec3 ea{0.5, 1.02, -1}, eb{0.5, -1, 1.02};
  EXPECT_FALSE(warped_square_crossing(ea, eb, s, t, nullptr).has_value());
  WarpTable w;
  EXPECT_FALSE(warped_square_crossing(ea, eb, s, t, &w).has_value());  // no corner moved
  const double a = 1 / (8 * std::sqrt(2.0));
  w.insert(corner_of(t, 0), Warp{-1, {0, -a, -a}});
  w.insert(corner_of(t, 1), Warp{-1, {1, -a, -a}});
  const std::optional<Vec3> x = warped_square_crossing(ea, eb, s, t, &w);
  ASSERT_TRUE(x.has_value());
  const double y = (0.02 * (1 + a) + a) / (1 + 2 * a);
  EXPECT_NEAR(x->x, 0.5, 1e-15);
  EXPECT_NEAR(x->y, y, 1e-12);
  EXPECT_NEAR(x->z, 0.02 - y, 1e-12);
  EXPECT_TRUE(within_ulp_of_segment(*x, ea, eb));
  // The crossing with the y = 0 face moves symmetrically (to (y, z) =
  // (0.02 - y, y)), so the two I vertices, 0.02 sqrt(2) < h/32 apart on the
  // prewarped faces, end sqrt(2) (2y - 0.02) > h/16 apart (Lemma 6's bound).
  const double apart = std::sqrt(2.0) * (y - (0.02 - y));
  EXPECT_GT(apart, 1.0 / 16);
  EXPECT_LT(std::sqrt(2.0) * 0.02, 1.0 / 32);
  // E parallel to the square's mean plane (along x): no crossing.
  EXPECT_FALSE(warped_square_crossing({-1, 0.5, -0.01}, {2, 0.5, -0.01}, s, t, &w).has_value());
}

TEST(WarpRules, FirstPassLooksAtWholeBoxEdges) {
  // P = [1/64, 2] x [-1, 2] x [-1, 1/4]; E, between the top facet (z = 1/4)
  // and the facet x = 1/64, is the line (1/64, y, 1/4). Root cube [0, 1]^3,
  // h = 1. The box vertex v = (0, 0, 1) has ring neighbours (0, 0, 1/2) (a
  // smaller neighbour's corner splits the box edge x = y = 0) and (1, 0, 1):
  // both ring segments stay >= 1/4 > h/8 from E, and v is >= 3/4 from both
  // facets (neither pass moves it). The whole box edge x = y = 0, z in
  // [0, 1], passes 1/64 < h/8 from E: §4.3's first pass moves v h/8 along
  // cross(E, z) = x, away from E (E is at x = 1/64 > 0): to (-1/8, 0, 1).
  // Sides kept: the planes x = 1/64 and z = 1/4, and the segment to
  // (1, 0, 1), crossed by x = 1/64, still passes above E's line.
  const OctTree t(RootCube<3>{{0, 0, 0}, 1});
  const CornerSet corners(t, t.leaves());
  const Domain3 d = make_domain(test::box({1.0 / 64, -1, -1}, {2, 2, 0.25}));
  const int f = facet_at(d, {1, 0, 0.25}), g = facet_at(d, {1.0 / 64, 0, 0});
  ASSERT_GE(f, 0);
  ASSERT_GE(g, 0);
  const GridPoint v = corner_of(t, 4), below = corner_of(t, 0);
  GridPoint mid = v;
  mid.f[2] = (v.f[2] + below.f[2]) / 2;
  const std::vector<GridPoint> ring = {mid, corner_of(t, 5)};
  const std::vector<WarpCandidateRecord> segments_only = {{v, {f, g}, ring, {}, 0, {}}};
  EXPECT_EQ(warp_box_vertices(t, corners, d, make_warp_candidates(segments_only)).find(v), nullptr);
  const std::vector<WarpCandidateRecord> with_edge = {{v, {f, g}, ring, {}, 0, {{below, v}}}};
  const WarpTable w = warp_box_vertices(t, corners, d, make_warp_candidates(with_edge));
  const Warp* moved = w.find(v);
  ASSERT_NE(moved, nullptr);
  EXPECT_EQ(moved->at.x, -1.0 / 8);
  EXPECT_EQ(moved->at.y, 0.0);
  EXPECT_EQ(moved->at.z, 1.0);
  EXPECT_EQ(w.first_pass, 1);
  EXPECT_EQ(w.conflicts, 0);
}

}  // namespace
}  // namespace pqmesh::tet3d
