// Hand cases for §5.2 (delta and the two vertex cases), each derived here.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nosteiner2d/exact_corner.hpp"
#include "nosteiner2d/stages.hpp"

namespace pqmesh {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Vec2> regular(int n) {
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) p.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)});
  return p;
}

// Unit square: every vertex is at distance 1 from its neighbours and from
// the two sides not at it, so delta(V) = 1; a side is at distance 1 from the
// opposite side, so delta(E) = 1. Right angles are Case 1: R is the square
// inset by 1/4, [1/4, 3/4]^2, with the same vertex order.
TEST(ShrinkRHand, UnitSquare) {
  const PolygonR r = shrink_q_to_r({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  ASSERT_TRUE(r.valid) << r.failure;
  EXPECT_EQ(r.case1, 4);
  EXPECT_EQ(r.case2, 0);
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(r.delta.vertex[0][std::size_t(k)], 1.0);
    EXPECT_DOUBLE_EQ(r.delta.side[0][std::size_t(k)], 1.0);
  }
  const Vec2 want[4] = {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
  ASSERT_EQ(r.loops[0].size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(r.loops[0][std::size_t(k)].x, want[k].x, 1e-15);
    EXPECT_NEAR(r.loops[0][std::size_t(k)].y, want[k].y, 1e-15);
  }
}

// Exact 3 pi/4 test (the Case 1 / Case 2 decision) on exact corners at the
// origin with next = (1, 0): prev = (-1, 1) is exactly 3 pi/4 (Case 1, the
// tie); (-1, 1 -+ 2^-40) opens / closes it by ~2^-41 rad; (1, -1) is reflex
// (7 pi/4), (-1, 0) straight, (0, 1) right.
TEST(ShrinkRHand, ThreeQuarterPiDecision) {
  const Vec2 v{0, 0}, next{1, 0};
  const double e = std::ldexp(1.0, -40);
  EXPECT_TRUE(detail::angle_at_most_three_quarter_pi({-1, 1}, v, next));
  EXPECT_FALSE(detail::angle_at_most_three_quarter_pi({-1, 1 - e}, v, next));
  EXPECT_TRUE(detail::angle_at_most_three_quarter_pi({-1, 1 + e}, v, next));
  EXPECT_FALSE(detail::angle_at_most_three_quarter_pi({1, -1}, v, next));
  EXPECT_FALSE(detail::angle_at_most_three_quarter_pi({-1, 0}, v, next));
  EXPECT_TRUE(detail::angle_at_most_three_quarter_pi({0, 1}, v, next));
}

// Regular n-gon, n >= 5: delta(V) = the side s (its neighbours; every other
// face is farther), delta(E) = s. Interior angle pi - 2 pi/n: n = 8 gives
// exactly 3 pi/4 in exact arithmetic, but its rounded vertices decide; n = 12
// is Case 2 everywhere (24 R vertices), n = 6 Case 1 (6 R vertices).
TEST(ShrinkRHand, RegularPolygons) {
  for (int n : {6, 12, 40}) {
    const PolygonR r = shrink_q_to_r({regular(n)});
    ASSERT_TRUE(r.valid) << r.failure;
    const double side = 2 * std::sin(kPi / n);
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(r.delta.vertex[0][std::size_t(k)], side, 1e-12);
      EXPECT_NEAR(r.delta.side[0][std::size_t(k)], side, 1e-12);
    }
    const bool case2 = n > 8;
    EXPECT_EQ(r.case2, case2 ? n : 0);
    EXPECT_EQ(r.loops[0].size(), std::size_t(case2 ? 2 * n : n));
    // Every R vertex is at distance side/4 from the lines of its Q sides,
    // so (Case 1) at radius cos(pi/n) - side/4 / ... measured as: distance
    // from the centre >= apothem - side/4 - 1e-12 and < 1.
    const double apothem = std::cos(kPi / n);
    for (const Vec2 w : r.loops[0]) {
      const double rho = std::hypot(w.x, w.y);
      EXPECT_LT(rho, 1.0);
      EXPECT_GE(rho, apothem - side / 4 - 1e-12);
    }
  }
}

}  // namespace
}  // namespace pqmesh
