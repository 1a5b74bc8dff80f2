// Tetrahedron measures against values derived by hand (thesis ch. 3;
// docs/algorithm/quality.md "Quality measures").
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "pqmesh/quality.hpp"

namespace pqmesh {
namespace {

constexpr double kTol = 1e-12;
const double kDeg = 180.0 / std::acos(-1.0);
const double kInf = std::numeric_limits<double>::infinity();

// Regular tetrahedron on alternate cube corners, edge a = 2 sqrt2 (order chosen
// so det(b-a, c-a, d-a) = +16 > 0). Volume a^3/(6 sqrt2) = 8/3. Circumcentre
// the origin, R = sqrt3 = (sqrt6/4) a; inradius r = (sqrt6/12) a = sqrt3/3.
// The circumsphere is the smallest enclosing ball (all faces acute, and the
// 4th vertex is at height sqrt(2/3) a > face circumradius a/sqrt3), so aspect
// = sphere ratio = 3. All six dihedral angles are arccos(1/3).
TEST(TetrahedronQuality, Regular) {
  const Vec3 a{1, 1, 1}, b{1, -1, -1}, c{-1, -1, 1}, d{-1, 1, -1};
  const TetQuality q = tetrahedron_quality(a, b, c, d);
  EXPECT_NEAR(q.volume, 8.0 / 3.0, kTol);
  EXPECT_NEAR(q.aspect_ratio, 3.0, kTol);
  EXPECT_NEAR(q.sphere_ratio, 3.0, kTol);
  EXPECT_NEAR(q.radius_edge, std::sqrt(6.0) / 4, kTol);
  EXPECT_NEAR(q.min_dihedral_deg, std::acos(1.0 / 3) * kDeg, 1e-10);
  EXPECT_NEAR(q.max_dihedral_deg, std::acos(1.0 / 3) * kDeg, 1e-10);
  EXPECT_NEAR(circumradius(a, b, c, d), std::sqrt(3.0), kTol);
  EXPECT_NEAR(enclosing_radius(a, b, c, d), std::sqrt(3.0), kTol);
  EXPECT_NEAR(inradius(a, b, c, d), std::sqrt(3.0) / 3, kTol);
}

// The same tetrahedron with two vertices swapped: volume -8/3, same shape.
TEST(TetrahedronQuality, InvertedHasNegativeVolumeSameShape) {
  const TetQuality q = tetrahedron_quality({1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1});
  EXPECT_NEAR(q.volume, -8.0 / 3.0, kTol);
  EXPECT_NEAR(q.aspect_ratio, 3.0, kTol);
  EXPECT_NEAR(q.min_dihedral_deg, std::acos(1.0 / 3) * kDeg, 1e-10);
}

// Corner tetrahedron O, e1, e2, e3. V = 1/6. Circumcentre (1/2,1/2,1/2),
// R = sqrt3/2. The face e1 e2 e3 is equilateral with side sqrt2, circumradius
// sqrt2/sqrt3 = sqrt6/3 ~ 0.816 about its centroid (1/3,1/3,1/3); the origin is
// at distance sqrt3/3 ~ 0.577 from it, so that face's circumcircle ball
// encloses the tetrahedron; no edge ball does (the longest edges, sqrt2, have
// radius 0.707 and e.g. the ball on e1 e2, centre (1/2,1/2,0), misses e3 at
// distance sqrt(3/2)). So R_enc = sqrt6/3 < R.
// Faces: three right triangles of area 1/2, one equilateral of area
// (sqrt3/4)(sqrt2)^2 = sqrt3/2; S = (3 + sqrt3)/2, r = 3V/S = 1/(3 + sqrt3).
// aspect = (sqrt6/3)(3 + sqrt3) = sqrt6 + sqrt2; sphere = (sqrt3/2)(3 + sqrt3)
// = (3 sqrt3 + 3)/2; radius-edge = R/1 = sqrt3/2 (shortest edges have length 1).
// Dihedrals: 90 at the three axis edges (coordinate planes), and between the
// slanted face (normal (1,1,1)/sqrt3) and a coordinate plane arccos(1/sqrt3).
TEST(TetrahedronQuality, CornerEnclosedByFaceCircle) {
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  const TetQuality q = tetrahedron_quality(o, x, y, z);
  const double s2 = std::sqrt(2.0), s3 = std::sqrt(3.0), s6 = std::sqrt(6.0);
  EXPECT_NEAR(q.volume, 1.0 / 6.0, kTol);
  EXPECT_NEAR(enclosing_radius(o, x, y, z), s6 / 3, kTol);
  EXPECT_NEAR(circumradius(o, x, y, z), s3 / 2, kTol);
  EXPECT_NEAR(inradius(o, x, y, z), 1 / (3 + s3), kTol);
  EXPECT_NEAR(q.aspect_ratio, s6 + s2, kTol);
  EXPECT_NEAR(q.sphere_ratio, (3 * s3 + 3) / 2, kTol);
  EXPECT_NEAR(q.radius_edge, s3 / 2, kTol);
  EXPECT_NEAR(q.min_dihedral_deg, std::acos(1 / s3) * kDeg, 1e-10);
  EXPECT_NEAR(q.max_dihedral_deg, 90.0, 1e-10);
}

// Needle a = (-10,0,0), b = (10,0,0), c = (0,1,0), d = (0,0,1).
// det(b-a, c-a, d-a) = det((20,0,0),(10,1,0),(10,0,1)) = 20, V = 10/3.
// The diametral ball of ab (centre O, radius 10) holds c and d (distance 1),
// and no ball is smaller than half the diameter: R_enc = 10.
// Faces: abc (z = 0) and abd (y = 0) have area 20*1/2 = 10; acd has area vector
// (c-a) x (d-a) = (10,1,0) x (10,0,1) = (1,-10,-10), area sqrt201/2, and bcd
// the mirror image. S = 20 + sqrt201, r = 3V/S = 10/(20 + sqrt201),
// aspect = 10/r = 20 + sqrt201.
// Circumcentre (0,t,t) by symmetry; |a - C|^2 = 100 + 2t^2 = |c - C|^2 =
// t^2 + (t-1)^2 gives t = -99/2, R^2 = 100 + 2 (99/2)^2 = 5000.5.
// sphere = sqrt5000.5 (20 + sqrt201)/10; shortest edge cd = sqrt2, so
// radius-edge = sqrt(5000.5/2) = sqrt2500.25 (~50.0024999375; not 50.0025,
// whose square is 2500.25000625).
// Dihedrals with outward normals n: cos = -n1.n2. At ab: 90. At ac (faces abc,
// n = (0,0,-1), and acd, n = (-1,10,10)/sqrt201): 10/sqrt201, same at ad, bc, bd
// (~45.2 deg, the minimum). At cd (faces acd and bcd, n = (-1,10,10)/sqrt201
// and (1,10,10)/sqrt201): cos = -199/201 (~171.9 deg, the maximum).
TEST(TetrahedronQuality, NeedleEnclosedByEdgeBall) {
  const Vec3 a{-10, 0, 0}, b{10, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  const TetQuality q = tetrahedron_quality(a, b, c, d);
  const double s201 = std::sqrt(201.0);
  EXPECT_NEAR(q.volume, 10.0 / 3.0, kTol);
  EXPECT_NEAR(enclosing_radius(a, b, c, d), 10.0, kTol);
  EXPECT_NEAR(circumradius(a, b, c, d), std::sqrt(5000.5), 1e-10);
  EXPECT_NEAR(inradius(a, b, c, d), 10 / (20 + s201), kTol);
  EXPECT_NEAR(q.aspect_ratio, 20 + s201, 1e-11);
  EXPECT_NEAR(q.sphere_ratio, std::sqrt(5000.5) * (20 + s201) / 10, 1e-9);
  EXPECT_NEAR(q.radius_edge, std::sqrt(2500.25), 1e-10);
  EXPECT_NEAR(q.min_dihedral_deg, std::acos(10 / s201) * kDeg, 1e-10);
  EXPECT_NEAR(q.max_dihedral_deg, std::acos(-199.0 / 201.0) * kDeg, 1e-10);
}

// Sliver: the unit square's corners, alternate ones lifted by h:
// a = (0,0,0), b = (1,1,0), c = (0,1,h), d = (1,0,h) (det = +2h, V = h/3).
// Its symmetry group (180-degree turn about the vertical axis through
// (1/2,1/2), and the 90-degree turn combined with z -> h - z) fixes only
// (1/2,1/2,h/2), which is equidistant from all four vertices; the minimal ball
// is unique hence symmetric, so R_enc = R = sqrt(1/2 + h^2/4).
// All four faces are congruent with area |(c-a) x (d-a)|/2 = sqrt(1 + 2h^2)/2,
// so r = 3V/S = h / (2 sqrt(1 + 2h^2)) and aspect = sphere = 2 R sqrt(1+2h^2)/h.
// Dihedral at the diagonal ab: the perpendicular rays from (1/2,1/2,0) to c and
// d are (-1/2,1/2,h), (1/2,-1/2,h): cos = (h^2 - 1/2)/(h^2 + 1/2) (the maximum,
// near 180); at a side edge, e.g. a-d, the outward normals give
// cos = 1/(1 + 2h^2) (the minimum, near 0). h = 1 is the regular tetrahedron.
TEST(TetrahedronQuality, Sliver) {
  for (double h : {1.0, 0.1, 0.01, 1e-4}) {
    SCOPED_TRACE(h);
    const TetQuality q = tetrahedron_quality({0, 0, 0}, {1, 1, 0}, {0, 1, h}, {1, 0, h});
    const double R = std::sqrt(0.5 + h * h / 4);
    const double expected_aspect = 2 * R * std::sqrt(1 + 2 * h * h) / h;
    EXPECT_NEAR(q.volume, h / 3, 1e-15);
    EXPECT_NEAR(q.aspect_ratio / expected_aspect, 1.0, 1e-10);
    EXPECT_NEAR(q.sphere_ratio / expected_aspect, 1.0, 1e-10);
    EXPECT_NEAR(q.radius_edge, R / std::sqrt(1 + h * h), 1e-12);
    EXPECT_NEAR(q.min_dihedral_deg, std::acos(1 / (1 + 2 * h * h)) * kDeg, 1e-6);
    EXPECT_NEAR(q.max_dihedral_deg, std::acos((h * h - 0.5) / (h * h + 0.5)) * kDeg, 1e-6);
  }
  const TetQuality thin = tetrahedron_quality({0, 0, 0}, {1, 1, 0}, {0, 1, 1e-4}, {1, 0, 1e-4});
  EXPECT_GT(thin.aspect_ratio, 1e4);
  EXPECT_LT(thin.min_dihedral_deg, 0.05);
  EXPECT_GT(thin.max_dihedral_deg, 179.95);
}

// Flat (four coplanar points) and fully coincident tetrahedra: no crash, no
// NaN; ratios +infinity, dihedrals 0 and 180, volume exactly 0.
TEST(TetrahedronQuality, DegenerateIsInfinite) {
  for (const auto& t : {std::array<Vec3, 4>{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}},
                        std::array<Vec3, 4>{Vec3{0, 0, 0}, Vec3{1, 1, 1}, Vec3{2, 2, 2}, Vec3{3, 3, 3}},
                        std::array<Vec3, 4>{Vec3{5, 5, 5}, Vec3{5, 5, 5}, Vec3{5, 5, 5}, Vec3{5, 5, 5}}}) {
    const TetQuality q = tetrahedron_quality(t[0], t[1], t[2], t[3]);
    EXPECT_EQ(q.volume, 0.0);
    EXPECT_EQ(q.aspect_ratio, kInf);
    EXPECT_EQ(q.sphere_ratio, kInf);
    EXPECT_EQ(q.radius_edge, kInf);
    EXPECT_EQ(q.min_dihedral_deg, 0.0);
    EXPECT_EQ(q.max_dihedral_deg, 180.0);
    EXPECT_EQ(inradius(t[0], t[1], t[2], t[3]), 0.0);
    EXPECT_EQ(circumradius(t[0], t[1], t[2], t[3]), kInf);
  }
  // The flat unit square: the diagonal's diametral circle passes through the
  // other two corners (right angles), radius sqrt2/2.
  EXPECT_NEAR(enclosing_radius(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}), std::sqrt(0.5),
              kTol);
  // Collinear 0..3 along (1,1,1): the outer pair's ball, radius 3 sqrt3 / 2.
  EXPECT_NEAR(enclosing_radius(Vec3{0, 0, 0}, Vec3{1, 1, 1}, Vec3{2, 2, 2}, Vec3{3, 3, 3}), 1.5 * std::sqrt(3.0),
              kTol);
  EXPECT_EQ(enclosing_radius(Vec3{5, 5, 5}, Vec3{5, 5, 5}, Vec3{5, 5, 5}, Vec3{5, 5, 5}), 0.0);
}

}  // namespace
}  // namespace pqmesh
