// The small-integer stage of incircle (predicates.cpp,
// detail::incircle_small_integer) against an independent GMP oracle: it must
// answer on nearby dyadic grid points (the quadtree's cocircular corners) and
// give the exact sign, and refuse when the differences need more than 12
// bits or are inexact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "gmp_oracle.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

TEST(IncircleSmallInteger, GridPointsAnswerExactly) {
  std::mt19937_64 rng(31);
  int answered = 0, zero = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    // Offsets below 2^11 grid units from a common dyadic origin: differences
    // need at most 12 bits, so the stage must answer.
    const int range = trial % 2 == 0 ? 3 : 2048;
    const double unit = std::ldexp(1.0, static_cast<int>(rng() % 60) - 40);
    const double ox = std::ldexp(static_cast<double>(rng() % 4096), -3), oy = std::ldexp(static_cast<double>(rng() % 4096), -3);
    Vec2 p[4];
    for (auto& v : p)
      v = {ox + static_cast<double>(rng() % static_cast<std::uint64_t>(range)) * unit,
           oy + static_cast<double>(rng() % static_cast<std::uint64_t>(range)) * unit};
    Sign s = Sign::Zero;
    const bool ok = detail::incircle_small_integer(p[0], p[1], p[2], p[3], s);
    const Sign o = test::incircle_oracle(p[0], p[1], p[2], p[3]);
    if (ok) {
      ++answered;
      EXPECT_EQ(s, o) << "trial " << trial;
    }
    EXPECT_EQ(incircle(p[0], p[1], p[2], p[3]), o);
    zero += o == Sign::Zero;
  }
  EXPECT_GT(answered, 90000);  // floor: nearly all of these are in the stage's range
  EXPECT_GT(zero, 1000);       // floor: many exactly cocircular (or collinear) sets
}

TEST(IncircleSmallInteger, RefusesWideOrInexactDifferences) {
  Sign s = Sign::Zero;
  // 13 bits: 4096 units apart.
  EXPECT_FALSE(detail::incircle_small_integer({4096, 0}, {0, 1}, {-1, 0}, {0, 0}, s));
  EXPECT_TRUE(detail::incircle_small_integer({2047, 0}, {0, 1}, {-1, 0}, {0, 0}, s));
  EXPECT_EQ(s, test::incircle_oracle({2047, 0}, {0, 1}, {-1, 0}, {0, 0}));
  // Full-precision coordinates: many bits.
  EXPECT_FALSE(detail::incircle_small_integer({0.1, 0}, {0, 0.3}, {-0.7, 0}, {0, 0}, s));
  // An inexact difference (1 - 2^-60 rounds).
  EXPECT_FALSE(detail::incircle_small_integer({1, 0}, {0, 1}, {-1, 0}, {0x1p-60, 0}, s));
  // Four equal points.
  EXPECT_TRUE(detail::incircle_small_integer({1, 1}, {1, 1}, {1, 1}, {1, 1}, s));
  EXPECT_EQ(s, Sign::Zero);
  // A unit square's corners are cocircular; its centre is inside.
  EXPECT_TRUE(detail::incircle_small_integer({0, 0}, {1, 0}, {1, 1}, {0, 1}, s));
  EXPECT_EQ(s, Sign::Zero);
  EXPECT_TRUE(detail::incircle_small_integer({0, 0}, {1, 0}, {1, 1}, {0.5, 0.5}, s));
  EXPECT_EQ(s, Sign::Positive);
}

}  // namespace
}  // namespace pqmesh
