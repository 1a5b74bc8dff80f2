// The shared double filter of the predicates (predicates.hpp,
// detail::filtered_sign): a sign only when it is certain, silence otherwise;
// and incircle, which uses it, against an independent GMP oracle on clear,
// near-cocircular and exactly cocircular inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>

#include "gmp_oracle.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

// Sign the filter reports, or nullopt when it stays silent (the sign is
// preset, to see that a silent filter leaves it untouched).
std::optional<Sign> filtered(double det, double permanent, double factor, bool no_tiny_factor = true) {
  Sign s = Sign::Negative;
  if (detail::filtered_sign(det, permanent, factor, s, [&] { return no_tiny_factor; })) return s;
  EXPECT_EQ(s, Sign::Negative) << "a silent filter must leave the sign alone";
  return std::nullopt;
}

TEST(FilteredSign, DecidesOnlyOutsideTheBound) {
  const double eps = std::numeric_limits<double>::epsilon();
  // bound = 8 eps * permanent; permanent 1 gives bound 8 eps.
  EXPECT_EQ(filtered(9 * eps, 1.0, 8), Sign::Positive);
  EXPECT_EQ(filtered(-9 * eps, 1.0, 8), Sign::Negative);
  EXPECT_FALSE(filtered(8 * eps, 1.0, 8).has_value());  // not strictly above the bound
  EXPECT_FALSE(filtered(0.0, 1.0, 8).has_value());      // an exact zero is never claimed
  EXPECT_FALSE(filtered(7 * eps, 1.0, 8).has_value());
  EXPECT_EQ(filtered(7 * eps, 1.0, 4), Sign::Positive);  // the factor scales the bound
}

TEST(FilteredSign, ZeroPermanentTinyPermanentAndNaN) {
  EXPECT_EQ(filtered(0.0, 0.0, 8), Sign::Zero);  // every term exactly zero
  // A zero permanent from factors so small that a product may have underflowed: silent.
  EXPECT_FALSE(filtered(0.0, 0.0, 8, /*no_tiny_factor=*/false).has_value());
  EXPECT_TRUE(detail::no_tiny_factor(0.0, 0x1p-200, -0x1p-200, 1.0));
  EXPECT_FALSE(detail::no_tiny_factor(0.0, 0x1p-201));
  EXPECT_FALSE(detail::no_tiny_factor(-0x1p-600, 1.0));
  // Below kTinyPermanent underflow could spoil the bound: silent even for a clear det.
  EXPECT_FALSE(filtered(1e-290, 1e-290, 8).has_value());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(filtered(nan, 1.0, 8).has_value());
  EXPECT_FALSE(filtered(1.0, nan, 8).has_value());
}

TEST(IncircleWithSharedFilter, ExactOnTiesNearTiesAndClearCases) {
  // The corners of an axis-parallel square and of a tilted one are
  // cocircular: exactly Zero (the filter must stay silent on them).
  EXPECT_EQ(incircle({0, 0}, {1, 0}, {1, 1}, {0, 1}), Sign::Zero);
  EXPECT_EQ(incircle({0, 1}, {1, 0}, {2, 1}, {1, 2}), Sign::Zero);
  EXPECT_EQ(incircle({0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}), Sign::Zero);  // permanent 0
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  int nonzero = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec2 p[4];
    for (auto& v : p) v = {coord(rng), coord(rng)};
    if (trial % 2 == 1) {  // near-cocircular: rounded points of one circle
      const double t = coord(rng) * 3.14159;
      for (int k = 0; k < 4; ++k) p[k] = {0.1 + 0.7 * std::cos(t + 1.5 * k), -0.2 + 0.7 * std::sin(t + 1.5 * k)};
    }
    const Sign exact = test::incircle_oracle(p[0], p[1], p[2], p[3]);
    nonzero += exact != Sign::Zero;
    ASSERT_EQ(incircle(p[0], p[1], p[2], p[3]), exact) << "trial " << trial;
  }
  EXPECT_GT(nonzero, 10000);  // the clear half at least (the cases are not all ties)
}

}  // namespace
}  // namespace pqmesh
