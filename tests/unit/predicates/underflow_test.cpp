// The predicates on coordinates so small that the double filter's products
// underflow (predicates.hpp, detail::no_tiny_factor): a permanent of exactly 0
// then says nothing, and the exact stages must decide. Every predicate is a
// homogeneous polynomial in the coordinate differences, so scaling all points
// by a power of two (exact for these coordinates) keeps its sign: the sign at
// scale 2^-600 must be the sign at scale 1, and the GMP oracles agree.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gmp_oracle.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

constexpr double kTiny = 0x1p-600;  // products of two differences underflow to 0

Vec2 scaled(Vec2 p) { return {p.x * kTiny, p.y * kTiny}; }
Vec3 scaled(Vec3 p) { return {p.x * kTiny, p.y * kTiny, p.z * kTiny}; }

TEST(PredicatesUnderflow, TheRightTriangleAtTinyScaleIsNotFlat) {
  // The case that was reported Zero: orient2d's permanent underflows to 0.
  EXPECT_EQ(orient2d({0, 0}, {kTiny, 0}, {0, kTiny}), Sign::Positive);
  EXPECT_EQ(dot_sign(Vec3{0, 0, 0}, Vec3{kTiny, 0, 0}, Vec3{0, 0, 0}, Vec3{kTiny, 0, 0}), Sign::Positive);
  EXPECT_EQ(orient3d({0, 0, 0}, {kTiny, 0, 0}, {0, kTiny, 0}, {0, 0, kTiny}), Sign::Positive);
}

TEST(PredicatesUnderflow, SignsAtScale2ToMinus600EqualSignsAtScale1) {
  std::mt19937_64 rng(20261202);
  std::uniform_int_distribution<int> small(-3, 3);  // small integers: many exact ties too
  const auto v2 = [&] { return Vec2{double(small(rng)), double(small(rng))}; };
  const auto v3 = [&] { return Vec3{double(small(rng)), double(small(rng)), double(small(rng))}; };
  int nonzero = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vec2 a = v2(), b = v2(), c = v2(), d = v2();
    const Vec3 p = v3(), q = v3(), r = v3(), s = v3(), t = v3();
    const Sign o2 = orient2d(a, b, c), o3 = orient3d(p, q, r, s);
    nonzero += o2 != Sign::Zero;
    ASSERT_EQ(o2, test::orient2d_oracle(a, b, c));
    ASSERT_EQ(orient2d(scaled(a), scaled(b), scaled(c)), o2) << "trial " << trial;
    ASSERT_EQ(test::orient2d_oracle(scaled(a), scaled(b), scaled(c)), o2);
    ASSERT_EQ(incircle(scaled(a), scaled(b), scaled(c), scaled(d)), incircle(a, b, c, d)) << "trial " << trial;
    ASSERT_EQ(dot_sign(scaled(a), scaled(b), scaled(c)), dot_sign(a, b, c)) << "trial " << trial;
    ASSERT_EQ(orient3d(scaled(p), scaled(q), scaled(r), scaled(s)), o3) << "trial " << trial;
    ASSERT_EQ(test::orient3d_oracle(scaled(p), scaled(q), scaled(r), scaled(s)), o3);
    ASSERT_EQ(dot_sign(scaled(p), scaled(q), scaled(r), scaled(s)), dot_sign(p, q, r, s)) << "trial " << trial;
    if (o3 != Sign::Zero) {  // insphere asks for a positive (or reoriented) tetrahedron
      ASSERT_EQ(insphere(scaled(p), scaled(q), scaled(r), scaled(s), scaled(t)), insphere(p, q, r, s, t))
          << "trial " << trial;
    }
  }
  EXPECT_GT(nonzero, 1000);  // not all degenerate
}

}  // namespace
}  // namespace pqmesh
