// tetrahedron_aspect_within(a, b, c, d, orient3d(a, b, c, d), limit) must
// answer exactly tetrahedron_quality(a, b, c, d).aspect_ratio <= limit: checked
// over seeded random shapes, grid shapes (right angles, circumcentres on a
// face), slivers and needles (circumcentres far outside: the enclosing ball
// decides), every scale from 2^-400 to 2^400 and flat tetrahedra, at limits
// on both sides of the aspect ratio and of the sphere ratio by one ulp, between
// the two, and at 0, infinity and NaN.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "predicates/predicates.hpp"
#include "pqmesh/quality.hpp"
#include "quality/tetrahedron_aspect_within.hpp"

namespace pqmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void expect_same_answers(const std::array<Vec3, 4>& p) {
  const TetQuality q = tetrahedron_quality(p[0], p[1], p[2], p[3]);
  const Sign s = orient3d(p[0], p[1], p[2], p[3]);
  const double a = q.aspect_ratio, r = q.sphere_ratio;
  const std::array<double, 11> limits = {a, std::nextafter(a, 0.0), std::nextafter(a, kInf), r,
                                         std::nextafter(r, 0.0), std::nextafter(r, kInf), 0.5 * (a + r), 0.0, 3.0,
                                         kInf, std::numeric_limits<double>::quiet_NaN()};
  for (const double limit : limits)
    EXPECT_EQ(tetrahedron_aspect_within(p[0], p[1], p[2], p[3], s, limit), a <= limit)
        << "aspect " << a << " sphere ratio " << r << " limit " << limit;
}

TEST(AspectWithin, RandomTetrahedraAnswerAsTheFullQuality) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {u(rng), u(rng), u(rng)};
    expect_same_answers(p);
  }
}

TEST(AspectWithin, GridTetrahedraAnswerAsTheFullQuality) {
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> g(0, 3);
  for (int i = 0; i < 20000; ++i) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {0.125 * g(rng), 0.125 * g(rng), 0.125 * g(rng)};
    expect_same_answers(p);
  }
}

TEST(AspectWithin, SliversAndNeedlesAnswerAsTheFullQuality) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0), h(-1e-6, 1e-6);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a{u(rng), u(rng), 0}, b{u(rng), u(rng), 0}, c{u(rng), u(rng), 0};
    const Vec3 d = i % 2 == 0 ? Vec3{u(rng), u(rng), h(rng)} : Vec3{a.x + h(rng), a.y + h(rng), h(rng)};
    expect_same_answers({a, b, c, d});
  }
}

TEST(AspectWithin, EveryScaleAnswersAsTheFullQuality) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-400, 400);
  for (int i = 0; i < 20000; ++i) {
    const int e = scale(rng);
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {std::ldexp(u(rng), e), std::ldexp(u(rng), e), std::ldexp(u(rng), e)};
    expect_same_answers(p);
  }
}

TEST(AspectWithin, FlatTetrahedraAreWithinOnlyAnInfiniteLimit) {
  const std::array<Vec3, 4> flat = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.25, 0.25, 0}};
  ASSERT_EQ(orient3d(flat[0], flat[1], flat[2], flat[3]), Sign::Zero);
  expect_same_answers(flat);
  EXPECT_TRUE(tetrahedron_aspect_within(flat[0], flat[1], flat[2], flat[3], Sign::Zero, kInf));
  EXPECT_FALSE(tetrahedron_aspect_within(flat[0], flat[1], flat[2], flat[3], Sign::Zero, 1e300));
}

}  // namespace
}  // namespace pqmesh
