// next_up / next_down (predicates.hpp), the ulp box steps of the rounding rule,
// are the same doubles as std::nextafter towards +-infinity: special values
// (zeros, subnormals, the largest double, infinities, NaN) and seeded random
// bit patterns of every sign and exponent.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

void expect_like_nextafter(double x) {
  const double inf = std::numeric_limits<double>::infinity();
  const double up = std::nextafter(x, inf), down = std::nextafter(x, -inf);
  if (std::isnan(x)) {
    EXPECT_TRUE(std::isnan(next_up(x)));
    EXPECT_TRUE(std::isnan(next_down(x)));
    return;
  }
  // Bit patterns: -0 and +0 must come out as nextafter gives them.
  EXPECT_EQ(std::bit_cast<std::uint64_t>(next_up(x)), std::bit_cast<std::uint64_t>(up)) << x;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(next_down(x)), std::bit_cast<std::uint64_t>(down)) << x;
}

TEST(NextDouble, SpecialValues) {
  using L = std::numeric_limits<double>;
  for (const double x : {0.0, -0.0, L::denorm_min(), -L::denorm_min(), L::min(), -L::min(), L::max(), -L::max(),
                         L::infinity(), -L::infinity(), L::quiet_NaN(), 1.0, -1.0, 0.5, -0.5, 3.0, 0x1p-1022,
                         0x1p-1022 - L::denorm_min(), -0x1p-1022 + L::denorm_min()})
    expect_like_nextafter(x);
}

TEST(NextDouble, RandomBitPatterns) {
  std::mt19937_64 rng(42);
  for (int i = 0; i < 200000; ++i) expect_like_nextafter(std::bit_cast<double>(rng()));
}

}  // namespace
}  // namespace pqmesh
