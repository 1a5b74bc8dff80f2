// The vertex fan bound (src/nosteiner2d/fan_bound.hpp;
// docs/algorithm/nosteiner2d.md "The fan bound") against brute force: the
// best fan found by dynamic programming over a fine grid of spokes (angles
// j alpha / 72, lengths on a geometric grid through both end lengths), from
// the spoke (0, 1) to the spoke (alpha, R), never beats fan_bound(alpha, R)
// (the bound is never below a fan actually found) and reaches 0.85 of it
// (sharp up to the grid spacing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "improve2d/triangle_angles.hpp"
#include "nosteiner2d/fan_bound.hpp"

namespace pqmesh {
namespace {

// The largest min angle of a fan at the origin whose spokes lie on the grid;
// best[j][m] = the best fan from the first spoke to spoke (angle j, length m).
double brute_force_fan(double alpha, double ratio) {
  constexpr int kAngles = 72;
  const double log_r = std::log(ratio), step = log_r > 0 ? log_r / 48 : 1.0 / 48;
  const int m_lo = -24, m_hi = (log_r > 0 ? 48 : 0) + 24, m_count = m_hi - m_lo + 1;
  auto spoke = [&](int j, int m) {
    const double phi = alpha * j / kAngles, len = std::exp(step * m);
    return Vec2{len * std::cos(phi), len * std::sin(phi)};
  };
  std::vector<std::vector<double>> best(kAngles + 1, std::vector<double>(std::size_t(m_count), -1));
  best[0][std::size_t(-m_lo)] = std::numbers::pi;  // the first spoke, length 1
  for (int j = 1; j <= kAngles; ++j)
    for (int m = m_lo; m <= m_hi; ++m) {
      const Vec2 q = spoke(j, m);
      double b = -1;
      for (int i = 0; i < j; ++i) {
        if (alpha * (j - i) / kAngles >= std::numbers::pi) continue;  // not a counter-clockwise triangle
        for (int l = m_lo; l <= m_hi; ++l) {
          const double prev = best[std::size_t(i)][std::size_t(l - m_lo)];
          if (prev <= b) continue;
          b = std::max(b, std::min(prev, detail::min_angle({0, 0}, spoke(i, l), q)));
        }
      }
      best[std::size_t(j)][std::size_t(m - m_lo)] = b;
    }
  return best[kAngles][std::size_t((log_r > 0 ? 48 : 0) - m_lo)];
}

TEST(FanBound, AgainstBruteForce) {
  const double pi = std::numbers::pi;
  struct Case {
    double alpha, ratio;
  };
  // A square corner (45 degrees), a 60-degree corner (60), the tiny notch's
  // corner (90 degrees, sides 0.4995 and 0.001), a comb slot's bottom corner
  // (270 degrees, 1/2 against 1/512), a thin corner, a straight angle, a
  // nearly full turn.
  for (const Case c : {Case{pi / 2, 1}, Case{pi / 3, 1}, Case{pi / 2, 499.5}, Case{1.5 * pi, 256}, Case{0.2, 10},
                       Case{pi, 50}, Case{1.9 * pi, 1000}}) {
    SCOPED_TRACE(testing::Message() << "alpha " << c.alpha << ", ratio " << c.ratio);
    const double bound = detail::fan_bound(c.alpha, c.ratio), found = brute_force_fan(c.alpha, c.ratio);
    std::printf("  fan alpha %.4f, ratio %g: bound %.4f deg, best grid fan %.4f deg\n", c.alpha, c.ratio,
                bound * 180 / pi, found * 180 / pi);
    EXPECT_LE(found, bound * (1 + 1e-9));
    EXPECT_GE(found, 0.85 * bound);
    EXPECT_LE(bound, std::min(c.alpha, pi / 3) * (1 + 1e-12));
  }
  EXPECT_NEAR(detail::fan_bound(pi / 2, 1), pi / 4, 1e-12);  // two right isosceles triangles
  EXPECT_NEAR(detail::fan_bound(pi / 3, 1), pi / 3, 1e-12);  // one equilateral triangle
}

// The bound decreases as the ratio grows and increases with the corner angle
// up to the equilateral cap (monotone in both, as the proof's feasibility is).
TEST(FanBound, Monotone) {
  double prev = 10;
  for (double r = 1; r < 1e12; r *= 3) {
    const double b = detail::fan_bound(std::numbers::pi / 2, r);
    EXPECT_LE(b, prev * (1 + 1e-12));
    prev = b;
  }
  EXPECT_LT(prev, 0.1);
}

}  // namespace
}  // namespace pqmesh
