// The 3D rounding rule of the checker (within_ulp_of_segment / within_ulp_of_plane,
// predicates.hpp; docs/algorithm/quality.md "The validity checker") against an
// independent oracle in 128-bit integer arithmetic: segments and planes with
// small integer data, points a few ulps around a correctly rounded point of
// them. All tested points lie in [8, 32), where doubles are multiples of 2^-49,
// so scaling by 2^50 makes them integers below 2^55 and every product below
// stays under 2^110.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

__extension__ typedef __int128 I128;
constexpr double kScale = 1125899906842624.0;  // 2^50

// x * 2^50 as an integer; exact for 8 <= |x| < 32 or small integers.
I128 scaled(double x) {
  const double s = x * kScale;  // exact: a power-of-two scaling
  EXPECT_EQ(std::floor(s), s) << x;
  EXPECT_LT(std::abs(s), 9.0e18) << x;
  return static_cast<I128>(static_cast<std::int64_t>(s));
}

struct UlpBox {
  double lo[3], hi[3];
};

UlpBox ulp_box(Vec3 p) {
  const double inf = std::numeric_limits<double>::infinity();
  const double c[3] = {p.x, p.y, p.z};
  UlpBox b{};
  for (int i = 0; i < 3; ++i) b.lo[i] = std::nextafter(c[i], -inf), b.hi[i] = std::nextafter(c[i], inf);
  return b;
}

// Plane n . x = d (integers) meets the box: the linear function takes both
// signs or zero over the corners.
bool plane_oracle(Vec3 p, const int n[3], int d) {
  const UlpBox b = ulp_box(p);
  I128 mn = 0, mx = 0;
  for (int i = 0; i < 3; ++i) {
    const I128 l = n[i] * scaled(b.lo[i]), h = n[i] * scaled(b.hi[i]);
    mn += std::min(l, h);
    mx += std::max(l, h);
  }
  const I128 rhs = static_cast<I128>(d) * scaled(1.0);
  return mn <= rhs && rhs <= mx;
}

// Segment a + t (b - a), t in [0, 1], a and b integer points, meets the box:
// the per-axis parameter intervals, rationals (num / den) with den = D * 2^50,
// have a common point with [0, 1].
// (denominators D * 2^50 < 2^53, numerators < 2^56.)
bool segment_oracle(Vec3 p, const int a[3], const int b[3]) {
  const UlpBox box = ulp_box(p);
  // Current interval [lo_num/lo_den, hi_num/hi_den], denominators positive.
  I128 lo_num = 0, lo_den = 1, hi_num = 1, hi_den = 1;
  for (int i = 0; i < 3; ++i) {
    const I128 A = static_cast<I128>(a[i]) * scaled(1.0);
    const int D = b[i] - a[i];
    if (D == 0) {
      if (A < scaled(box.lo[i]) || A > scaled(box.hi[i])) return false;
      continue;
    }
    I128 n0 = scaled(box.lo[i]) - A, n1 = scaled(box.hi[i]) - A;
    I128 den = static_cast<I128>(D) * scaled(1.0);
    if (den < 0) n0 = -n0, n1 = -n1, den = -den, std::swap(n0, n1);
    // t in [n0/den, n1/den]
    if (n0 * lo_den > lo_num * den) lo_num = n0, lo_den = den;
    if (n1 * hi_den < hi_num * den) hi_num = n1, hi_den = den;
  }
  return lo_num * hi_den <= hi_num * lo_den;
}

TEST(UlpRule3d, SegmentAgreesWithOracle) {
  std::mt19937 rng(20261130);
  std::uniform_int_distribution<int> coord(10, 16), step(1, 96), jitter(-2, 2);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    int a[3], b[3];
    for (int i = 0; i < 3; ++i) a[i] = coord(rng), b[i] = coord(rng);
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) continue;
    const int n = 97, k = step(rng);
    // The correctly rounded point at t = k / n: one division of exact integers.
    double c[3];
    for (int i = 0; i < 3; ++i) c[i] = static_cast<double>(a[i] * n + (b[i] - a[i]) * k) / n;
    const Vec3 exact_rounding{c[0], c[1], c[2]};
    const Vec3 A{static_cast<double>(a[0]), static_cast<double>(a[1]), static_cast<double>(a[2])};
    const Vec3 B{static_cast<double>(b[0]), static_cast<double>(b[1]), static_cast<double>(b[2])};
    EXPECT_TRUE(within_ulp_of_segment(exact_rounding, A, B));
    // A few ulps away in random directions.
    for (int i = 0; i < 3; ++i)
      for (int s = jitter(rng); s != 0; s += s > 0 ? -1 : 1)
        c[i] = std::nextafter(c[i], s > 0 ? 64.0 : 0.0);
    const Vec3 q{c[0], c[1], c[2]};
    const bool expected = segment_oracle(q, a, b);
    EXPECT_EQ(within_ulp_of_segment(q, A, B), expected) << trial;
    (expected ? inside : outside)++;
  }
  EXPECT_GT(inside, 500);
  EXPECT_GT(outside, 500);
}

TEST(UlpRule3d, PlaneAgreesWithOracle) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> normal(-3, 3), offset(-32, 32), jitter(-3, 3);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    int n[3];
    for (int& v : n) v = normal(rng);
    if (n[2] == 0) n[2] = 1;
    // The plane n . x = D through the integer point Q0, spanned by the
    // integer directions (n2, 0, -n0) and (0, n2, -n1), both orthogonal to n.
    const Vec3 Q0{12, 12, 20};
    const int D = n[0] * 12 + n[1] * 12 + n[2] * 20;
    const Vec3 Q1 = Q0 + Vec3{static_cast<double>(n[2]), 0, static_cast<double>(-n[0])};
    const Vec3 Q2 = Q0 + Vec3{0, static_cast<double>(n[2]), static_cast<double>(-n[1])};
    // A correctly rounded point of the plane: x, y dyadic in [11, 13], z by
    // one division of an exact numerator (z in [14, 26]).
    const double x = 12 + offset(rng) / 32.0, y = 12 + offset(rng) / 32.0;
    double c[3] = {x, y, (D - n[0] * x - n[1] * y) / n[2]};
    EXPECT_TRUE(within_ulp_of_plane({c[0], c[1], c[2]}, Q0, Q1, Q2));
    for (int i = 0; i < 3; ++i)
      for (int s = jitter(rng); s != 0; s += s > 0 ? -1 : 1) c[i] = std::nextafter(c[i], s > 0 ? 64.0 : 0.0);
    const Vec3 q{c[0], c[1], c[2]};
    const bool expected = plane_oracle(q, n, D);
    EXPECT_EQ(within_ulp_of_plane(q, Q0, Q1, Q2), expected) << trial;
    (expected ? inside : outside)++;
  }
  EXPECT_GT(inside, 500);
  EXPECT_GT(outside, 500);
}

}  // namespace
}  // namespace pqmesh
