#include "predicates/predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pqmesh {
namespace {

TEST(Orient2d, BasicSigns) {
  EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), Sign::Positive);
  EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), Sign::Negative);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), Sign::Zero);
}

// Points on the line y = x with coordinates near 0.5 whose naive double
// determinant is polluted by rounding: the exact answer is derived from the
// exact dyadic values (a point p + k*ulp on the diagonal is collinear; moving
// one coordinate by one ulp makes the sign that of the move).
TEST(Orient2d, NearDegenerateIsExact) {
  const double ulp = std::nextafter(0.5, 1.0) - 0.5;
  for (int i = 0; i < 64; ++i) {
    const double x = 0.5 + i * ulp;
    EXPECT_EQ(orient2d({12, 12}, {24, 24}, {x, x}), Sign::Zero) << i;
    EXPECT_EQ(orient2d({12, 12}, {24, 24}, {x, x + ulp}), Sign::Positive) << i;
    EXPECT_EQ(orient2d({12, 12}, {24, 24}, {x + ulp, x}), Sign::Negative) << i;
  }
}

TEST(Orient3d, ConventionIsPositiveVolume) {
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), Sign::Positive);
  EXPECT_EQ(orient3d({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}), Sign::Negative);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 7, 0}), Sign::Zero);
}

TEST(Orient3d, NearCoplanarIsExact) {
  const double ulp = std::nextafter(1.0, 2.0) - 1.0;
  // Plane z = 0.1*x + 0.2*y is not exactly representable; use z = x/2 + y/4 with
  // dyadic coefficients so points on it are exact, then nudge z by one ulp.
  for (int i = 1; i < 50; ++i) {
    const double x = 1.0 + i * ulp * 3, y = 1.0 - i * ulp * 2;
    const double z = x / 2 + y / 4;  // exact: both terms lie on the 2^-53 grid near 0.75
    const Vec3 a{0, 0, 0}, b{4, 0, 2}, c{0, 4, 1};
    EXPECT_EQ(orient3d(a, b, c, {x, y, z}), Sign::Zero) << i;
    const Sign above = orient3d(a, b, c, {x, y, std::nextafter(z, 10.0)});
    const Sign below = orient3d(a, b, c, {x, y, std::nextafter(z, -10.0)});
    EXPECT_NE(above, Sign::Zero);
    EXPECT_EQ(below, -above);
  }
}

TEST(Orient2dProjected, KeepsCyclicAxisOrder) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};  // normal +z
  EXPECT_EQ(orient2d_projected(a, b, c, 2), Sign::Positive);
  const Vec3 d{0, 0, 0}, e{0, 1, 0}, f{0, 0, 1};  // normal +x
  EXPECT_EQ(orient2d_projected(d, e, f, 0), Sign::Positive);
  const Vec3 g{0, 0, 0}, h{0, 0, 1}, k{1, 0, 0};  // normal +y
  EXPECT_EQ(orient2d_projected(g, h, k, 1), Sign::Positive);
}

TEST(Incircle, UnitCircle) {
  const Vec2 a{1, 0}, b{0, 1}, c{-1, 0};
  EXPECT_EQ(incircle(a, b, c, {0, 0}), Sign::Positive);
  EXPECT_EQ(incircle(a, b, c, {0, -1}), Sign::Zero);
  EXPECT_EQ(incircle(a, b, c, {0, -1.0000001}), Sign::Negative);
  EXPECT_EQ(incircle(a, c, b, {0, 0}), Sign::Negative);  // clockwise flips
}

TEST(Insphere, UnitSphere) {
  const Vec3 a{1, 0, 0}, b{0, 1, 0}, c{-1, 0, 0}, d{0, 0, 1};
  ASSERT_EQ(orient3d(a, b, c, d), Sign::Positive);
  EXPECT_EQ(insphere(a, b, c, d, {0, 0, 0}), Sign::Positive);
  EXPECT_EQ(insphere(a, b, c, d, {0, 0, -1}), Sign::Zero);
  EXPECT_EQ(insphere(a, b, c, d, {0, 0, -2}), Sign::Negative);
  EXPECT_EQ(insphere(a, b, c, d, {0, -1, 0}), Sign::Zero);
}

// Cospherical points on the sphere of radius 5 (3-4-5 triples): exact Zero,
// even after translation by an amount that makes the double arithmetic inexact.
TEST(Insphere, CosphericalAfterTranslationIsZero) {
  const Vec3 t{1e6 + 0.125, -3e5 + 0.5, 0.0625};
  const Vec3 a = Vec3{5, 0, 0} + t, b = Vec3{0, 5, 0} + t, c = Vec3{-3, 4, 0} + t, d = Vec3{0, 0, 5} + t;
  const Vec3 e = Vec3{0, 3, -4} + t;
  const Sign o = orient3d(a, b, c, d);
  ASSERT_NE(o, Sign::Zero);
  EXPECT_EQ(insphere(a, b, c, d, e), Sign::Zero);
}

TEST(DotSign, AngleClasses) {
  EXPECT_EQ(dot_sign(Vec2{0, 0}, Vec2{1, 0}, Vec2{1, 1}), Sign::Positive);
  EXPECT_EQ(dot_sign(Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}), Sign::Zero);
  EXPECT_EQ(dot_sign(Vec2{0, 0}, Vec2{1, 0}, Vec2{-1, 1}), Sign::Negative);
  EXPECT_EQ(dot_sign(Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 1}), Sign::Zero);
}

// Property: orient3d is antisymmetric under swapping two points and agrees
// with the double determinant whenever that one is far from zero.
TEST(Orient3d, RandomAntisymmetry) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)},
        d{u(rng), u(rng), u(rng)};
    EXPECT_EQ(orient3d(a, b, c, d), -orient3d(b, a, c, d));
    EXPECT_EQ(orient3d(a, b, c, d), orient3d(b, c, a, d));
    const double v = dot(cross(b - a, c - a), d - a);
    if (std::abs(v) > 1e-9) {
      EXPECT_EQ(orient3d(a, b, c, d), sign_of(v));
    }
  }
}

}  // namespace
}  // namespace pqmesh
