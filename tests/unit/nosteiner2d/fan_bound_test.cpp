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

// Whether p lies strictly inside the counter-clockwise triangle abc.
bool strictly_inside(Vec2 a, Vec2 b, Vec2 c, Vec2 p) {
  return cross(b - a, p - a) > 0 && cross(c - b, p - b) > 0 && cross(a - c, p - c) > 0;
}

// The best fan at the origin from the spoke (0, 1) past the direction omega
// of an obstacle at distance r (no triangle contains it in its interior):
// spokes on 48 angles j omega / 24 (up to 2 omega, below pi per triangle) and
// geometric lengths from r / 4 to 1, the spoke at omega no longer than r; the
// best over the spokes at angle >= omega.
double brute_force_obstacle(double omega, double r) {
  constexpr int kAngles = 48, kLengths = 64;
  const Vec2 q = {r * std::cos(omega), r * std::sin(omega)};
  const double step = std::log(4 / r) / kLengths;
  auto spoke = [&](int j, int m) {
    const double phi = omega * j / 24, len = std::exp(-step * m);
    return Vec2{len * std::cos(phi), len * std::sin(phi)};
  };
  std::vector<std::vector<double>> best(kAngles + 1, std::vector<double>(kLengths + 1, -1));
  best[0][0] = std::numbers::pi;
  double out = 0;
  for (int j = 1; j <= kAngles; ++j)
    for (int m = 0; m <= kLengths; ++m) {
      const Vec2 p = spoke(j, m);
      double b = -1;
      // A spoke in the obstacle's direction ends at or before it (an edge holds no point of dP inside).
      if (j == 24 && std::exp(-step * m) > r) continue;
      for (int i = 0; i < j; ++i) {
        if (omega * (j - i) / 24 >= std::numbers::pi) continue;
        for (int l = 0; l <= kLengths; ++l) {
          const double prev = best[std::size_t(i)][std::size_t(l)];
          if (prev <= b) continue;
          const Vec2 o = spoke(i, l);
          if (strictly_inside({0, 0}, o, p, q)) continue;
          b = std::max(b, std::min(prev, detail::min_angle({0, 0}, o, p)));
        }
      }
      best[std::size_t(j)][std::size_t(m)] = b;
      if (j >= 24) out = std::max(out, b);
    }
  return out;
}

// The obstacle fan bound against brute force: never below a fan found, and
// reaching 0.8 of it (measured 0.86-0.99 on these five; the proof relaxes the
// part of the triangle beyond the obstacle's direction).
TEST(FanBound, ObstacleAgainstBruteForce) {
  const double pi = std::numbers::pi;
  struct Case {
    double omega, r;
  };
  for (const Case c : {Case{pi / 20, 1.0 / 24}, Case{pi / 2, 1.0 / 100}, Case{pi / 6, 0.5}, Case{0.05, 0.2},
                       Case{pi, 1.0 / 50}}) {
    SCOPED_TRACE(testing::Message() << "omega " << c.omega << ", r " << c.r);
    const double bound = detail::obstacle_fan_bound(c.omega, 1 / c.r), found = brute_force_obstacle(c.omega, c.r);
    std::printf("  obstacle omega %.4f, r %g: bound %.4f deg, best grid fan %.4f deg\n", c.omega, c.r,
                bound * 180 / pi, found * 180 / pi);
    EXPECT_LE(found, bound * (1 + 1e-9));
    EXPECT_GE(found, 0.8 * bound);
  }
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
