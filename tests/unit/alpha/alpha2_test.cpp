// alpha for 2D polygons with holes: the smallest interior corner angle.
// Expected values are elementary; each test says how it was derived.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "pqmesh/alpha.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh {
namespace {

constexpr double kPi = std::numbers::pi;

bool is_edge(const FaceRef& f, int p, int q) {
  return f.kind == FaceRef::Kind::Edge && f.a == std::min(p, q) && f.b == std::max(p, q);
}

TEST(Alpha2, Square) {
  const AlphaResult r = compute_alpha({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2, 3}});
  EXPECT_NEAR(r.radians, kPi / 2, 1e-15);
  EXPECT_EQ(r.kind, "edge-edge");
}

TEST(Alpha2, LShapeReflexCornerIsNotMinimal) {
  // Corners 90 except vertex 3 = (1,1), which is 270 (reflex, measured inside).
  const std::vector<Vec2> v{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const AlphaResult r = compute_alpha(v, {{0, 1, 2, 3, 4, 5}});
  EXPECT_NEAR(r.radians, kPi / 2, 1e-15);
  EXPECT_NE(r.apex, 3);
  // Rotating the loop so the reflex corner comes first must not change alpha
  // (the reflex corner's 270 would win only if angles were measured outside).
  const AlphaResult s = compute_alpha(v, {{3, 4, 5, 0, 1, 2}});
  EXPECT_NEAR(s.radians, kPi / 2, 1e-15);
  EXPECT_NE(s.apex, 3);
}

TEST(Alpha2, TenDegreeSpike) {
  // Tip (1,0) joined to (0, -h) and (0, h) with h = tan(5 deg): the tip angle
  // is 2 atan(h) = 10 degrees. Other corners: (-1,-1) and (-1,1) make about 48
  // degrees, (0,-h) and (0,h) are reflex.
  const double h = std::tan(5 * kPi / 180);
  const AlphaResult r = compute_alpha({{-1, -1}, {0, -h}, {1, 0}, {0, h}, {-1, 1}}, {{0, 1, 2, 3, 4}});
  EXPECT_NEAR(r.degrees(), 10.0, 1e-9);
  EXPECT_EQ(r.apex, 2);
  EXPECT_TRUE(is_edge(r.first, 1, 2));
  EXPECT_TRUE(is_edge(r.second, 2, 3));
  EXPECT_NE(r.describe(0).find("vertex 2: edge 1-2 and edge 2-3"), std::string::npos) << r.describe(0);
  EXPECT_NE(r.describe(1).find("vertex 3: edge 2-3 and edge 3-4"), std::string::npos) << r.describe(1);
}

TEST(Alpha2, ThirtySixtyNinetyTriangle) {
  // Legs sqrt(3) (along x) and 1 (along y): the angle opposite the short leg,
  // at (sqrt(3), 0), is atan(1/sqrt(3)) = 30 degrees; the others 60 and 90.
  const AlphaResult r = compute_alpha({{0, 0}, {std::sqrt(3.0), 0}, {0, 1}}, {{0, 1, 2}});
  EXPECT_NEAR(r.degrees(), 30.0, 1e-12);
  EXPECT_EQ(r.apex, 1);
  EXPECT_TRUE(is_edge(r.first, 0, 1));
  EXPECT_TRUE(is_edge(r.second, 1, 2));
}

TEST(Alpha2, HoleCornersAreMeasuredInsideTheDomain) {
  // Square [0,4]^2 with a clockwise triangular hole; the hole's corners are
  // seen from the domain as 360 minus the triangle's angles (>= 270 here),
  // so alpha stays 90 even though the hole triangle has a 45 degree corner.
  const std::vector<Vec2> v{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {1, 3}};
  const AlphaResult r = compute_alpha(v, {{0, 1, 2, 3}, {4, 6, 5}});
  EXPECT_NEAR(r.radians, kPi / 2, 1e-15);
  EXPECT_LT(r.apex, 4);
}

TEST(Alpha2, RejectsBadLoops) {
  EXPECT_THROW(compute_alpha({{0, 0}, {1, 0}}, {{0, 1}}), DomainError);
  EXPECT_THROW(compute_alpha({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 7}}), DomainError);
  EXPECT_THROW(compute_alpha({{0, 0}, {1, 0}, {0, 1}}, {}), DomainError);
  // A zero-angle fold: 0 -> 1 -> 2 with 2 back on the ray 1->0.
  EXPECT_THROW(compute_alpha({{0, 0}, {2, 0}, {1, 0}, {1, 1}}, {{0, 1, 2, 3}}), DomainError);
}

}  // namespace
}  // namespace pqmesh
