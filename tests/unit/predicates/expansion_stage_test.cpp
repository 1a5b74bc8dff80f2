// The expansion stage of orient2d (predicates.cpp, detail::orient2d_expansion)
// against an independent GMP oracle, on the inputs it exists for: points with
// full 53-bit coordinates on, or a few ulps off, a slanted line (the filter and
// the certified stage cannot decide those), exactly collinear points built by
// construction, and random points at widely different scales. Also checks its
// range guard and that orient2d as a whole agrees with the oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "gmp_oracle.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

// Checks the stage (it must answer: every input here is in its range) and the
// whole predicate against the oracle; returns the sign.
Sign checked(Vec2 a, Vec2 b, Vec2 c) {
  Sign s = Sign::Zero;
  EXPECT_TRUE(detail::orient2d_expansion(a, b, c, s));
  const Sign o = test::orient2d_oracle(a, b, c);
  EXPECT_EQ(s, o) << a.x << ' ' << a.y << ' ' << b.x << ' ' << b.y << ' ' << c.x << ' ' << c.y;
  EXPECT_EQ(orient2d(a, b, c), o);
  return o;
}

TEST(ExpansionStage, PointsNearSlantedSegments) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  int positive = 0, negative = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 60) - 30);
    const Vec2 a{unit(rng) * scale, unit(rng) * scale}, b{unit(rng) * scale, unit(rng) * scale};
    const double t = 0.5 * (unit(rng) + 1.0);
    // A rounded point of the line through a and b, then its ulp neighbours:
    // all within a few ulps of the line, so the double filter rarely decides.
    const Vec2 p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        Vec2 c = p;
        if (dx != 0) c.x = std::nextafter(c.x, dx * inf);
        if (dy != 0) c.y = std::nextafter(c.y, dy * inf);
        const Sign s = checked(a, b, c);
        positive += s == Sign::Positive;
        negative += s == Sign::Negative;
      }
  }
  // Both strict sides must occur often: the inputs really are near-degenerate
  // in both directions (a floor, not a measured count). Exact zeros are rare
  // here (a rounded point is seldom exactly on the line); CollinearByConstruction
  // covers them.
  EXPECT_GT(positive, 10000);
  EXPECT_GT(negative, 10000);
}

TEST(ExpansionStage, CollinearByConstruction) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int exact_count = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // a, b and a + k (b - a) for a dyadic k with a few bits and a direction
    // with few bits: every coordinate is exact, the three points collinear,
    // and the coordinates still have up to 53 significant bits.
    const Vec2 a{unit(rng), unit(rng)};
    const double dx = std::ldexp(static_cast<double>(rng() % 1024) - 512.0, -12);
    const double dy = std::ldexp(static_cast<double>(rng() % 1024) - 512.0, -12);
    const double k = std::ldexp(static_cast<double>(rng() % 64) - 32.0, -3);
    const Vec2 b{a.x + dx, a.y + dy}, c{a.x + k * dx, a.y + k * dy};
    // The construction is exact only where no sum rounded; the oracle decides
    // anyway, and Zero must come out whenever it is exact.
    const bool exact = b.x - a.x == dx && b.y - a.y == dy && c.x - a.x == k * dx && c.y - a.y == k * dy;
    const Sign s = checked(a, b, c);
    if (exact) {
      EXPECT_EQ(s, Sign::Zero);
      ++exact_count;
    }
    checked(b, c, a);
    checked(c, a, b);
  }
  EXPECT_GT(exact_count, 1000);  // floor: the exact constructions do occur
}

TEST(ExpansionStage, WideScalesAndZeros) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    Vec2 p[3];
    for (auto& v : p) {
      // Exponents spread over 390 binades per axis, within the stage's range.
      v.x = rng() % 5 == 0 ? 0.0 : std::ldexp(unit(rng), static_cast<int>(rng() % 390) - 195);
      v.y = rng() % 5 == 0 ? 0.0 : std::ldexp(unit(rng), static_cast<int>(rng() % 390) - 195);
    }
    checked(p[0], p[1], p[2]);
  }
}

TEST(ExpansionStage, RangeGuard) {
  const double inf = std::numeric_limits<double>::infinity();
  const double tiny = std::numeric_limits<double>::denorm_min();
  Sign s = Sign::Zero;
  // One axis spans more than 2^400 (1 and 2^-402 on x): no answer.
  EXPECT_FALSE(detail::orient2d_expansion({0x1p-402, 0}, {1, 0}, {0, 1}, s));
  EXPECT_FALSE(detail::orient2d_expansion({inf, 0}, {1, 0}, {0, 1}, s));
  // Each axis is scaled on its own: huge x with tiny y is fine, and so is the
  // ulp box of a point on the x axis (a corner a subnormal below 0) against
  // that axis, the case the quadtree mesher meets.
  EXPECT_TRUE(detail::orient2d_expansion({0x1p900, 0x1p-900}, {0x1p901, 0}, {0, 0x1p-899}, s));
  EXPECT_EQ(s, test::orient2d_oracle({0x1p900, 0x1p-900}, {0x1p901, 0}, {0, 0x1p-899}));
  EXPECT_TRUE(detail::orient2d_expansion({0, 0}, {1, 0}, {0.0039, -tiny}, s));
  EXPECT_EQ(s, Sign::Negative);
  EXPECT_TRUE(detail::orient2d_expansion({0, 0}, {1, 0}, {0.0039, tiny}, s));
  EXPECT_EQ(s, Sign::Positive);
  EXPECT_TRUE(detail::orient2d_expansion({0x1p-398, 0}, {1, 0}, {0, 1}, s));
  EXPECT_EQ(s, Sign::Positive);
  // Outside the range orient2d still answers exactly (GMP).
  const Vec2 a{0x1p-500, 0x1p-500}, b{1, 1};
  EXPECT_EQ(orient2d(a, b, {0.5, 0.5}), Sign::Zero);
  const Vec2 c{0.5, std::nextafter(0.5, 1.0)};
  EXPECT_EQ(orient2d(a, b, c), test::orient2d_oracle(a, b, c));
}

}  // namespace
}  // namespace pqmesh
