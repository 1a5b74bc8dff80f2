// The error-free second stage of orient2d/incircle (predicates.cpp) against an
// independent exact oracle: 128-bit integer arithmetic on points with integer
// coordinates times a power of two (the quadtree's grid corners are such
// points; they are cocircular and collinear all the time, so the double
// filter fails and the second stage decides), plus points with full 53-bit
// coordinates near degenerate positions, where the stage must defer to GMP.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

__extension__ typedef __int128 i128;

Sign sign128(i128 v) { return v > 0 ? Sign::Positive : (v < 0 ? Sign::Negative : Sign::Zero); }

// Exact determinants for integer points.
i128 orient_int(const std::int64_t p[3][2]) {
  const i128 ax = p[0][0] - p[2][0], ay = p[0][1] - p[2][1], bx = p[1][0] - p[2][0], by = p[1][1] - p[2][1];
  return ax * by - ay * bx;
}
i128 incircle_int(const std::int64_t p[4][2]) {
  i128 dx[3], dy[3], l[3];
  for (int i = 0; i < 3; ++i) {
    dx[i] = p[i][0] - p[3][0];
    dy[i] = p[i][1] - p[3][1];
    l[i] = dx[i] * dx[i] + dy[i] * dy[i];
  }
  return l[0] * (dx[1] * dy[2] - dy[1] * dx[2]) + l[1] * (dx[2] * dy[0] - dy[2] * dx[0]) +
         l[2] * (dx[0] * dy[1] - dy[0] * dx[1]);
}

TEST(CertifiedStage, GridPointsMatchIntegerOracle) {
  std::mt19937_64 rng(7);
  int zero_orient = 0, zero_incircle = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const int range = trial % 3 == 0 ? 4 : 64;  // small ranges: many exact degeneracies
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    const double offset = std::ldexp(static_cast<double>(rng() % 1024), -5);  // dyadic, exact
    std::int64_t p[4][2];
    Vec2 v[4];
    for (int i = 0; i < 4; ++i) {
      for (int k = 0; k < 2; ++k) p[i][k] = static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(range));
      // v = offset + p * scale: exact doubles, and orientation/incircle signs of
      // v equal those of p (translation and positive scaling preserve them).
      v[i] = {offset + static_cast<double>(p[i][0]) * scale, offset + static_cast<double>(p[i][1]) * scale};
    }
    const std::int64_t tri[3][2] = {{p[0][0], p[0][1]}, {p[1][0], p[1][1]}, {p[2][0], p[2][1]}};
    const Sign o = sign128(orient_int(tri));
    ASSERT_EQ(orient2d(v[0], v[1], v[2]), o) << "trial " << trial;
    zero_orient += o == Sign::Zero;
    if (o != Sign::Positive) continue;  // incircle wants a counter-clockwise triangle
    const Sign c = sign128(incircle_int(p));
    ASSERT_EQ(incircle(v[0], v[1], v[2], v[3]), c) << "trial " << trial;
    zero_incircle += c == Sign::Zero;
  }
  EXPECT_GT(zero_orient, 1000);
  EXPECT_GT(zero_incircle, 100);
}

// Points one ulp off a line or circle: the second stage must not certify a
// rounded value (it defers to GMP), so the sign is still the exact one.
TEST(CertifiedStage, NearDegenerateFullPrecisionPoints) {
  const Vec2 a{0.1, 0.1}, b{0.7, 0.7};
  const Vec2 on{0.5, 0.5};
  EXPECT_EQ(orient2d(a, b, on), Sign::Zero);
  EXPECT_EQ(orient2d(a, b, {0.5, std::nextafter(0.5, 1.0)}), Sign::Positive);
  EXPECT_EQ(orient2d(a, b, {0.5, std::nextafter(0.5, 0.0)}), Sign::Negative);
  // The unit circle through (1,0), (0,1), (-1,0); (0,-1) is on it, one ulp in is inside.
  const Vec2 p{1, 0}, q{0, 1}, r{-1, 0};
  EXPECT_EQ(incircle(p, q, r, {0, -1}), Sign::Zero);
  EXPECT_EQ(incircle(p, q, r, {0, std::nextafter(-1.0, 0.0)}), Sign::Positive);
  EXPECT_EQ(incircle(p, q, r, {std::nextafter(0.0, 1.0), -1}), Sign::Negative);
}

}  // namespace
}  // namespace pqmesh
