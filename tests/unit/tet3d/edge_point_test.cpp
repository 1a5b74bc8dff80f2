// Points rounded onto a P edge (edge_point.hpp, the edge box's central vertex
// of §4.5.3): every result must satisfy the checker's rule
// within_ulp_of_segment (predicates.hpp), keep the requested coordinate on the
// segment's dominant axis, and lie near the exact point of the segment there.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "predicates/predicates.hpp"
#include "tet3d/points/edge_point.hpp"

namespace pqmesh::tet3d {
namespace {

double coord(const Vec3& p, int a) { return a == 0 ? p.x : (a == 1 ? p.y : p.z); }

TEST(EdgePoint, RoundedMidpointsLieWithinAnUlpOfTheSegment) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3, 3), t(0.05, 0.95);
  int tried = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    const double s = t(rng);
    const Vec3 m = a + s * (b - a);
    const Vec3 p = round_onto_segment(a, b, m);
    EXPECT_TRUE(within_ulp_of_segment(p, a, b));
    int d = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(coord(b, k) - coord(a, k)) > std::fabs(coord(b, d) - coord(a, d))) d = k;
    EXPECT_EQ(coord(p, d), coord(m, d));
    EXPECT_LT(norm(p - m), 1e-12 * (1 + norm(b - a)));
    ++tried;
  }
  EXPECT_EQ(tried, 2000);
  // Axis-parallel and degenerate-coordinate segments keep their exact coordinates.
  const Vec3 p = round_onto_segment({0.1, 0.3, 0.7}, {0.9, 0.3, 0.7}, {0.5, 0.31, 0.69});
  EXPECT_EQ(p.y, 0.3);
  EXPECT_EQ(p.z, 0.7);
  EXPECT_EQ(p.x, 0.5);
}

TEST(EdgePoint, ClipToABox) {
  const auto [t0, t1] = clip_segment({-1, 0.5, 0.5}, {3, 0.5, 0.5}, {0, 0, 0}, {1, 1, 1});
  EXPECT_DOUBLE_EQ(t0, 0.25);
  EXPECT_DOUBLE_EQ(t1, 0.5);
  const auto [s0, s1] = clip_segment({-1, 2, 0.5}, {3, 2, 0.5}, {0, 0, 0}, {1, 1, 1});
  EXPECT_GT(s0, s1);  // misses
}

}  // namespace
}  // namespace pqmesh::tet3d
