// within_ulp_of_plane_at_extremes (mesh/check3d_plane.hpp) against the
// eight-corner rule within_ulp_of_plane (predicates.hpp) it replaces in the
// checker and in the boundary markers: the same answer on points near slanted
// planes, on planes with zero normal components (parallel to an axis or a
// coordinate plane), and on points exactly on a plane.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "mesh/check3d_plane.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

struct Counts {
  int within = 0, outside = 0;
};

// Points a + s (b - a) + t (c - a) rounded (near the plane), then moved by
// up to `ulps` ulps per coordinate; every answer compared.
Counts compare_near(Vec3 a, Vec3 b, Vec3 c, std::mt19937_64& rng, int points, int ulps) {
  const auto normal = detail::plane_normal_signs(a, b, c);
  std::uniform_real_distribution<double> st(-0.5, 1.5);
  std::uniform_int_distribution<int> step(-ulps, ulps);
  Counts n;
  for (int i = 0; i < points; ++i) {
    const double s = st(rng), t = st(rng);
    Vec3 p = a + s * (b - a) + t * (c - a);
    double* xs[3] = {&p.x, &p.y, &p.z};
    for (double* x : xs) {
      const int k = step(rng);
      for (int j = 0; j < std::abs(k); ++j) *x = std::nextafter(*x, k > 0 ? INFINITY : -INFINITY);
    }
    const bool want = within_ulp_of_plane(p, a, b, c);
    EXPECT_EQ(detail::within_ulp_of_plane_at_extremes(p, a, b, c, normal), want)
        << "p = (" << p.x << ", " << p.y << ", " << p.z << ")";
    ++(want ? n.within : n.outside);
  }
  return n;
}

TEST(Check3dPlane, SameAnswerAsEightCornersNearSlantedPlanes) {
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> coord(-3.0, 3.0);
  Counts total;
  for (int plane = 0; plane < 200; ++plane) {
    const Vec3 a{coord(rng), coord(rng), coord(rng)}, b{coord(rng), coord(rng), coord(rng)},
        c{coord(rng), coord(rng), coord(rng)};
    if (orient2d_projected(a, b, c, 0) == Sign::Zero && orient2d_projected(a, b, c, 1) == Sign::Zero &&
        orient2d_projected(a, b, c, 2) == Sign::Zero)
      continue;  // collinear: no plane
    const Counts n = compare_near(a, b, c, rng, 50, 3);
    total.within += n.within;
    total.outside += n.outside;
  }
  // Both answers occur, so the comparison covers both branches.
  EXPECT_GT(total.within, 100);
  EXPECT_GT(total.outside, 100);
}

TEST(Check3dPlane, SameAnswerOnPlanesWithZeroNormalComponents) {
  std::mt19937_64 rng(7);
  // Planes normal to an axis (two zero components: decided by comparing
  // coordinates, no orient3d), a plane parallel to the z axis
  // (one zero component), a plane through dyadic points (exact constructions
  // land on it).
  const Vec3 planes[][3] = {{{0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}},
                            {{0.3, 0, 0}, {0.3, 1, 0}, {0.3, 0.2, 1}},
                            {{0.1, 0.3, 0}, {0.7, -0.2, 0}, {0.1, 0.3, 1}},
                            {{0, 0, 0}, {1, 0, 0.5}, {0, 1, 0.25}}};
  Counts total;
  for (const auto& p : planes) {
    const Counts n = compare_near(p[0], p[1], p[2], rng, 400, 2);
    total.within += n.within;
    total.outside += n.outside;
  }
  EXPECT_GT(total.within, 50);
  EXPECT_GT(total.outside, 50);
}

TEST(Check3dPlane, PointsOnThePlaneAreWithin) {
  // Exactly on the plane z = x / 2 + y / 4 (dyadic: no rounding).
  const Vec3 a{0, 0, 0}, b{1, 0, 0.5}, c{0, 1, 0.25};
  const auto normal = detail::plane_normal_signs(a, b, c);
  for (const Vec3 p : {Vec3{0.5, 0.5, 0.375}, Vec3{2, -4, 0}, Vec3{0, 0, 0}}) {
    ASSERT_EQ(orient3d(a, b, c, p), Sign::Zero);
    EXPECT_TRUE(detail::within_ulp_of_plane_at_extremes(p, a, b, c, normal));
  }
  // Off the plane by far more than an ulp.
  EXPECT_FALSE(detail::within_ulp_of_plane_at_extremes({0.5, 0.5, 0.5}, a, b, c, normal));
}

}  // namespace
}  // namespace pqmesh
