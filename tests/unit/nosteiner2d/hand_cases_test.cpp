// g(P) and the Steiner-free CDT on inputs whose values follow by hand from the
// definitions in pqmesh/nosteiner.hpp (thesis ch. 5 introduction, Thm 21).
// Each test states its derivation; coordinates are dyadic so the geometry is
// exactly the one described.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "nosteiner2d/stages.hpp"
#include "corpus2d.hpp"

namespace pqmesh {
namespace {

constexpr double kPi = std::numbers::pi;

using test::polygon;

void expect_valid_cdt(const Domain2& d) {
  const TriMesh2 m = steiner_free_cdt(d);
  const CheckReport r = check_mesh(m, d, CheckOptions{.no_boundary_steiner = true});
  EXPECT_TRUE(r.valid()) << r.to_text();
}

// Unit square. For V = (0,0), E towards (1,0): the only interfering faces
// within distance L(E) = 1 of V are the vertex (0,1) (r = 1, omega = pi/2)
// and the point (0,1) of the top side; the other points of the top side and
// the vertex (1,1) are farther than 1. So h = (pi/2) / max(1, 0) = pi/2, the
// same for every pair by symmetry, and every corner is pi/2: g = pi/2.
// The CDT is two right isosceles triangles: min angle pi/4.
TEST(SteinerFreeBound, UnitSquare) {
  const Domain2 d = polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const SteinerFreeBound b = steiner_free_bound(d);
  EXPECT_NEAR(b.g, kPi / 2, 1e-14);
  EXPECT_NEAR(b.vertex_term, kPi / 2, 1e-14);
  EXPECT_NEAR(b.pair_term, kPi / 2, 1e-14);
  ASSERT_EQ(b.spirals.size(), 8u);
  for (const EmptySpiral& e : b.spirals) {
    EXPECT_TRUE(e.has_eligible);
    EXPECT_EQ(e.shrink, 1.0);  // no eligible point with r < 1
  }
  EXPECT_NEAR(cdt_min_angle(d), kPi / 4, 1e-14);
  expect_valid_cdt(d);
}

// The four-point thin trapezoid of thesis Fig. 1.1: bottom E from V = (0,0)
// to U = (1,0), top side from A = (0.45, t) to B = (0.55, t), t = 1/64
// (0.45 and 0.55 are rounded doubles; the derivation uses their exact values).
//  - For (V, E): the interfering faces are A, B and the top side (the slanted
//    sides touch E). B is closer to U. A point (x, t) of the top side is
//    eligible for x <= 1/2 (equidistant allowed); there r ~ x in [0.45, 0.5],
//    so -ln r < 1 and h = omega = atan(t / x), smallest at x = 1/2:
//    h = atan(2t) -- realised on the side, not at a vertex.
//  - The mirror pair (U, E) gives the same value.
//  - No other pair is smaller: for the slanted sides no interfering point is
//    within their length except beyond-angle points with omega near the
//    obtuse corner angles; for the top side (L = 0.1) the bottom points within
//    0.1 of A have omega >= atan(t / 0.05) ~ 0.30.
//  - Corner angles: atan(t/0.45) at V and U, obtuse at A and B.
// So g = atan(2t) = atan(1/32). The empty spiral of (V, E): along the top side
// q = ln(rho)/phi ~ x ln(x) / t is increasing for x > 1/e, so its minimum is
// at A, a vertex (enumerated before the side): s = exp(ln|VA| / atan(t/0.45)).
// CDT: either diagonal gives the sliver V B A (or its mirror) with angle
// atan(t/0.45) - atan(t/0.55) at V, the smallest angle of both triangles.
TEST(SteinerFreeBound, ThinTrapezoidFigure1_1) {
  const double t = 1.0 / 64, xa = 0.45, xb = 0.55;
  const Domain2 d = polygon({{0, 0}, {1, 0}, {xb, t}, {xa, t}});
  const SteinerFreeBound b = steiner_free_bound(d);
  EXPECT_NEAR(b.g, std::atan(2 * t), 1e-13);
  EXPECT_NEAR(b.pair_term, std::atan(2 * t), 1e-13);
  ASSERT_GE(b.pair_spiral, 0);
  const EmptySpiral& best = b.spirals[b.pair_spiral];
  EXPECT_EQ(best.h_witness.face.kind, InterferingFace::Kind::Edge);
  EXPECT_NEAR(best.h_witness.point.x, 0.5, 1e-9);
  EXPECT_NEAR(best.h_witness.point.y, t, 1e-15);

  // The empty spiral of (V, E = V -> U): first spiral in enumeration order.
  const EmptySpiral& e = b.spirals[0];
  ASSERT_EQ(e.vertex, 0);
  ASSERT_EQ(e.other, 1);
  const double expected_q = std::log(std::hypot(xa, t)) / std::atan2(t, xa);
  EXPECT_NEAR(e.log_shrink, expected_q, 1e-12 * std::abs(expected_q));
  EXPECT_EQ(e.spiral_witness.face.kind, InterferingFace::Kind::Vertex);
  EXPECT_EQ(e.spiral_witness.face.a, 3);

  EXPECT_NEAR(cdt_min_angle(d), std::atan2(t, xa) - std::atan2(t, xb), 1e-13);
  EXPECT_LE(cdt_min_angle(d), kSteinerFreeBoundConstant * b.g);
  expect_valid_cdt(d);
}

// A reflex vertex R = (31/64, 1/128) close to the middle of the long bottom
// side V = (0,0) -> U = (1,0) of the unit square (a notch from the top side
// between (0.4,1) and (0.6,1) reaching down to R).
//  - (V, E): R is closer to V than to U (x < 1/2), |VR| < 1, in the sector,
//    r ~ 0.48 so -ln r < 1 and h = omega = atan((1/128) / (31/64)). Points of
//    the two notch sides near R have larger polar angle (their slope exceeds
//    the slope of VR by far) and rho >= 0.4 > 1/e, so they give more.
//  - (U, E): R is closer to V; the eligible part of the right notch side
//    starts at x = 1/2 where y > 0.1: larger.
//  - Pairs at R (sides of length ~1): the bottom points near R have r < 0.03
//    but omega > 1.5 (R's notch sides are nearly vertical), h >= ~0.45.
//  - Corner angles: pi/2 at the square's corners, > pi/2 at the notch top
//    corners, reflex at R.
// So g = atan(2/31 * 1/8) = atan(1/124).
TEST(SteinerFreeBound, ReflexVertexNearMiddleOfLongEdge) {
  const double xr = 31.0 / 64, yr = 1.0 / 128;
  const Domain2 d = polygon({{0, 0}, {1, 0}, {1, 1}, {0.6, 1}, {xr, yr}, {0.4, 1}, {0, 1}});
  const SteinerFreeBound b = steiner_free_bound(d);
  EXPECT_NEAR(b.g, std::atan2(yr, xr), 1e-14);
  ASSERT_GE(b.pair_spiral, 0);
  const EmptySpiral& best = b.spirals[b.pair_spiral];
  EXPECT_EQ(best.vertex, 0);
  EXPECT_EQ(best.other, 1);
  EXPECT_EQ(best.h_witness.face.kind, InterferingFace::Kind::Vertex);
  EXPECT_EQ(best.h_witness.face.a, 4);
  EXPECT_LE(cdt_min_angle(d), kSteinerFreeBoundConstant * b.g);
  expect_valid_cdt(d);
}

// A thin rectangle L x w: the top side interferes with the bottom side E
// though no top vertex is close; its point (L/2, w) gives omega = atan(2w/L)
// with r ~ 1/2 (h = omega), smaller than everything else (the top vertex
// above V has omega = pi/2). g = atan(2w/L): found only through the side.
TEST(SteinerFreeBound, ThinRectangleNeedsInterferingEdge) {
  const double L = 1, w = 1.0 / 256;
  const Domain2 d = polygon({{0, 0}, {L, 0}, {L, w}, {0, w}});
  const SteinerFreeBound b = steiner_free_bound(d);
  EXPECT_NEAR(b.g, std::atan(2 * w / L), 1e-14);
  EXPECT_EQ(b.spirals[b.pair_spiral].h_witness.face.kind, InterferingFace::Kind::Edge);
  EXPECT_LE(cdt_min_angle(d), kSteinerFreeBoundConstant * b.g);
  expect_valid_cdt(d);
}

// Regular n-gon on the unit circle. For a side E at V (length
// L = 2 sin(pi/n)) the only interfering point within L of V is the far end of
// the other side at V (r = 1, omega = the corner angle); every other vertex is
// at distance >= 2 sin(2 pi/n) > L. So g = pi - 2 pi/n. Every triangle of any
// triangulation of the vertices has inscribed angles >= pi/n, and the ear at
// a side has exactly pi/n: the CDT's min angle is pi/n (up to the rounding of
// the coordinates, which are not exactly cocircular).
TEST(SteinerFreeBound, RegularPolygon) {
  for (const int n : {5, 12, 100, 1000}) {
    std::vector<Vec2> pts;
    for (int i = 0; i < n; ++i) pts.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)});
    const Domain2 d = polygon(pts);
    const SteinerFreeBound b = steiner_free_bound(d);
    EXPECT_NEAR(b.g, kPi - 2 * kPi / n, 1e-9) << n;
    EXPECT_NEAR(cdt_min_angle(d), kPi / n, 1e-9) << n;
    expect_valid_cdt(d);
  }
}

}  // namespace
}  // namespace pqmesh
