// Triangle measures against values derived by hand (thesis ch. 3;
// docs/algorithm/quality.md "Quality measures").
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "pqmesh/quality.hpp"

namespace pqmesh {
namespace {

constexpr double kTol = 1e-12;
const double kRad = std::acos(-1.0) / 180.0;
const double kInf = std::numeric_limits<double>::infinity();

// Equilateral triangle, side a = 1: circumradius R = a/sqrt3, inradius
// r = A/s = (sqrt3/4)/(3/2) = a/(2 sqrt3); acute, so R_enc = R. Hence aspect =
// sphere ratio = 2 and radius-edge = R/a = 1/sqrt3.
TEST(TriangleQuality, Equilateral) {
  const Vec2 a{0, 0}, b{1, 0}, c{0.5, std::sqrt(3.0) / 2};
  const TriQuality q = triangle_quality(a, b, c);
  EXPECT_NEAR(q.min_angle_deg, 60.0, 1e-10);
  EXPECT_NEAR(q.max_angle_deg, 60.0, 1e-10);
  EXPECT_NEAR(q.aspect_ratio, 2.0, kTol);
  EXPECT_NEAR(q.sphere_ratio, 2.0, kTol);
  EXPECT_NEAR(q.radius_edge, 1 / std::sqrt(3.0), kTol);
  EXPECT_NEAR(q.area, std::sqrt(3.0) / 4, kTol);
  EXPECT_NEAR(circumradius(a, b, c), 1 / std::sqrt(3.0), kTol);
  EXPECT_NEAR(enclosing_radius(a, b, c), 1 / std::sqrt(3.0), kTol);
  EXPECT_NEAR(inradius(a, b, c), 1 / (2 * std::sqrt(3.0)), kTol);
}

// Right isosceles, legs 1: the right angle puts the hypotenuse's diametral
// circle through all three vertices, so R_enc = R = sqrt2/2. A = 1/2,
// s = (2 + sqrt2)/2, r = A/s = 1/(2 + sqrt2) = (2 - sqrt2)/2.
// aspect = sphere = sqrt2/(2 - sqrt2) = 1 + sqrt2; angles 45 and 90;
// radius-edge = (sqrt2/2)/1.
TEST(TriangleQuality, RightIsosceles) {
  const TriQuality q = triangle_quality({0, 0}, {1, 0}, {0, 1});
  EXPECT_NEAR(q.min_angle_deg, 45.0, 1e-10);
  EXPECT_NEAR(q.max_angle_deg, 90.0, 1e-10);
  EXPECT_NEAR(q.aspect_ratio, 1 + std::sqrt(2.0), kTol);
  EXPECT_NEAR(q.sphere_ratio, 1 + std::sqrt(2.0), kTol);
  EXPECT_NEAR(q.radius_edge, std::sqrt(2.0) / 2, kTol);
  EXPECT_NEAR(q.area, 0.5, kTol);
  EXPECT_NEAR(inradius(Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}), (2 - std::sqrt(2.0)) / 2, kTol);
}

// Obtuse (0,0), (4,0), (2,1): edges 4, sqrt5, sqrt5. Area = base 4 x height 1
// / 2 = 2 (the brief's "A = 4" is the cross product, twice the area).
// Circumradius = (4 sqrt5 sqrt5)/(4 A) = 20/8 = 2.5. The apex angle is obtuse
// ((0,0)-(2,1)).((4,0)-(2,1)) = (-2)(2) + (-1)(-1) = -3 < 0), so the smallest
// enclosing circle is the diametral circle of the long edge: R_enc = 2.
// s = (4 + 2 sqrt5)/2 = 2 + sqrt5, r = A/s = 2/(2 + sqrt5).
// aspect = 2/r = 2 + sqrt5; sphere = 2.5/r = 1.25 (2 + sqrt5).
// Angles: base atan(1/2) twice, apex 180 - 2 atan(1/2).
// radius-edge = 2.5/sqrt5 = sqrt5/2.
TEST(TriangleQuality, ObtuseEnclosingCircleIsNotCircumcircle) {
  const Vec2 a{0, 0}, b{4, 0}, c{2, 1};
  const TriQuality q = triangle_quality(a, b, c);
  const double s5 = std::sqrt(5.0);
  EXPECT_NEAR(enclosing_radius(a, b, c), 2.0, kTol);
  EXPECT_NEAR(circumradius(a, b, c), 2.5, kTol);
  EXPECT_NEAR(inradius(a, b, c), 2 / (2 + s5), kTol);
  EXPECT_NEAR(q.area, 2.0, kTol);
  EXPECT_NEAR(q.aspect_ratio, 2 + s5, kTol);
  EXPECT_NEAR(q.sphere_ratio, 1.25 * (2 + s5), kTol);
  EXPECT_NEAR(q.radius_edge, s5 / 2, kTol);
  EXPECT_NEAR(q.min_angle_deg, std::atan(0.5) / kRad, 1e-10);
  EXPECT_NEAR(q.max_angle_deg, 180 - 2 * std::atan(0.5) / kRad, 1e-10);
}

// The obtuse angle at each of the three corner positions (cyclic shifts keep
// the orientation): same values, so every branch of the enclosing-circle
// choice is exercised.
TEST(TriangleQuality, ObtuseAngleAtEachCorner) {
  const Vec2 p[3] = {{0, 0}, {4, 0}, {2, 1}};
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(k);
    const Vec2 a = p[k], b = p[(k + 1) % 3], c = p[(k + 2) % 3];
    EXPECT_NEAR(enclosing_radius(a, b, c), 2.0, kTol);
    const TriQuality q = triangle_quality(a, b, c);
    EXPECT_NEAR(q.aspect_ratio, 2 + std::sqrt(5.0), kTol);
    EXPECT_NEAR(q.sphere_ratio, 1.25 * (2 + std::sqrt(5.0)), kTol);
    EXPECT_NEAR(q.area, 2.0, kTol);
  }
}

// A clockwise copy has negative area and otherwise the same shape measures.
TEST(TriangleQuality, ClockwiseHasNegativeAreaSameShape) {
  const TriQuality ccw = triangle_quality({0, 0}, {4, 0}, {2, 1});
  const TriQuality cw = triangle_quality({0, 0}, {2, 1}, {4, 0});
  EXPECT_NEAR(cw.area, -2.0, kTol);
  EXPECT_DOUBLE_EQ(cw.aspect_ratio, ccw.aspect_ratio);
  EXPECT_DOUBLE_EQ(cw.sphere_ratio, ccw.sphere_ratio);
  EXPECT_DOUBLE_EQ(cw.min_angle_deg, ccw.min_angle_deg);
  EXPECT_DOUBLE_EQ(cw.max_angle_deg, ccw.max_angle_deg);
}

// Zero area (collinear, or coincident points) never crashes or yields NaN:
// ratios are +infinity, angles 0 and 180, area exactly 0.
TEST(TriangleQuality, DegenerateIsInfinite) {
  for (const auto& t : {std::array<Vec2, 3>{Vec2{0, 0}, Vec2{1, 1}, Vec2{2, 2}},
                        std::array<Vec2, 3>{Vec2{0, 0}, Vec2{0, 0}, Vec2{1, 0}},
                        std::array<Vec2, 3>{Vec2{3, 3}, Vec2{3, 3}, Vec2{3, 3}}}) {
    const TriQuality q = triangle_quality(t[0], t[1], t[2]);
    EXPECT_EQ(q.area, 0.0);
    EXPECT_EQ(q.aspect_ratio, kInf);
    EXPECT_EQ(q.sphere_ratio, kInf);
    EXPECT_EQ(q.radius_edge, kInf);
    EXPECT_EQ(q.min_angle_deg, 0.0);
    EXPECT_EQ(q.max_angle_deg, 180.0);
    EXPECT_EQ(inradius(t[0], t[1], t[2]), 0.0);
    EXPECT_EQ(circumradius(t[0], t[1], t[2]), kInf);
  }
  // Collinear (0,0),(1,1),(2,2): the enclosing circle is the diametral circle
  // of the outer pair, radius sqrt8/2 = sqrt2.
  EXPECT_NEAR(enclosing_radius(Vec2{0, 0}, Vec2{1, 1}, Vec2{2, 2}), std::sqrt(2.0), kTol);
}

// Nearly flat but not degenerate: finite, large, and sphere >= aspect >= 2
// (R >= R_enc because the circumcircle encloses the triangle; R_enc >= 2r, see
// tetrahedron_quality_test.cpp for the argument in d dimensions).
TEST(TriangleQuality, NearlyFlatIsFiniteAndOrdered) {
  const TriQuality q = triangle_quality({0, 0}, {1, 0}, {0.5, 1e-9});
  EXPECT_TRUE(std::isfinite(q.aspect_ratio));
  EXPECT_GT(q.aspect_ratio, 1e8);
  EXPECT_GE(q.sphere_ratio, q.aspect_ratio);
  EXPECT_LT(q.min_angle_deg, 1e-6);
  EXPECT_GT(q.max_angle_deg, 180 - 1e-6);
}

}  // namespace
}  // namespace pqmesh
