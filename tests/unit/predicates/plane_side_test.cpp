// PlaneSide (predicates/plane_side.hpp): orient3d against one fixed triangle
// through the precomputed exact plane N . d - K, and the two-corner ulp box
// test, against the independent GMP oracle and against within_ulp_of_plane
// (eight corners). Inputs: full-precision slanted triangles with points a few
// ulps around the plane along each axis (the settle search of
// tet3d/points/facet_plane.cpp; inexact differences), grid triangles with exactly
// coplanar points, axis-aligned and collinear triangles, zero coordinates,
// and coordinates outside the stage's range (orient3d decides those).
#include "predicates/plane_side.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gmp_oracle.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

using Tally = test::SignTally;

// PlaneSide's range: every coordinate zero or of magnitude in [2^-150, 2^150].
bool in_range(double v) { return v == 0 || (std::abs(v) >= 0x1p-150 && std::abs(v) <= 0x1p150); }
bool in_range(Vec3 p) { return in_range(p.x) && in_range(p.y) && in_range(p.z); }
bool tiny_or_in_range(Vec3 p) {
  for (const double v : {p.x, p.y, p.z})
    if (!in_range(v) && !(std::abs(v) < 0x1p-950)) return false;
  return true;
}
bool in_range(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return in_range(a) && in_range(b) && in_range(c) && in_range(d); }

// The stage answers exactly when the points are in its range, and both it and the whole predicate
// agree with the oracle; the ulp box test agrees with the eight-corner rule.
Sign checked(const PlaneSide& plane, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Sign o = test::orient3d_oracle(a, b, c, d);
  Sign s = Sign::Zero;
  const bool answered = plane.expansion_sign(d, s);
  // It must answer in the range; outside it only for tiny coordinates of d
  // (below 2^-950) with a, b, c in the range.
  if (in_range(a, b, c, d)) {
    EXPECT_TRUE(answered);
  }
  if (!(in_range(a) && in_range(b) && in_range(c) && tiny_or_in_range(d))) {
    EXPECT_FALSE(answered);
  }
  if (answered) {
    EXPECT_EQ(s, o);
  }
  EXPECT_EQ(plane(d), o);
  EXPECT_EQ(plane.meets_ulp_box(d), within_ulp_of_plane(d, a, b, c));
  return o;
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A point of the plane through a, b, c near (u, v) on the two other axes,
// rounded along `axis`, then moved by `ulps` doubles along that axis.
Vec3 near_plane(Vec3 a, Vec3 b, Vec3 c, int axis, double u, double v, int ulps) {
  const Vec3 n = cross(b - a, c - a);
  Vec3 p{};
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  axis_ref(p, j) = u;
  axis_ref(p, k) = v;
  const double ni = axis_coord(n, axis);
  const double x = axis_coord(a, axis) -
                   (axis_coord(n, j) * (u - axis_coord(a, j)) + axis_coord(n, k) * (v - axis_coord(a, k))) / ni;
  double y = x;
  for (int s = 0; s < std::abs(ulps); ++s) y = ulps > 0 ? next_up(y) : next_down(y);
  axis_ref(p, axis) = y;
  return p;
}

TEST(PlaneSide, FullPrecisionSlantedPlanesAroundTheCrossing) {
  std::mt19937_64 rng(20);
  Tally t;
  int meets = 0, misses = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    auto point = [&] {
      return Vec3{scale * uniform(rng, -10, 10), scale * uniform(rng, -10, 10), scale * uniform(rng, -10, 10)};
    };
    const Vec3 a = point(), b = point(), c = point();
    const PlaneSide plane(a, b, c);
    for (int q = 0; q < 40; ++q) {
      const int axis = static_cast<int>(rng() % 3);
      const Vec3 p = near_plane(a, b, c, axis, scale * uniform(rng, -10, 10), scale * uniform(rng, -10, 10),
                                static_cast<int>(rng() % 9) - 4);
      t.count(checked(plane, a, b, c, p));
      (plane.meets_ulp_box(p) ? meets : misses) += 1;
    }
  }
  EXPECT_GT(t.positive, 1000);
  EXPECT_GT(t.negative, 1000);
  EXPECT_GT(meets, 1000);
  EXPECT_GT(misses, 1000);
}

TEST(PlaneSide, GridPlanesWithCoplanarPoints) {
  std::mt19937_64 rng(21);
  Tally t;
  auto k = [&] { return static_cast<double>(static_cast<int>(rng() % 64) - 32); };
  for (int trial = 0; trial < 400; ++trial) {
    const int e = static_cast<int>(rng() % 20) - 10;
    auto grid = [&] { return Vec3{std::ldexp(k(), e), std::ldexp(k(), e), std::ldexp(k(), e)}; };
    const Vec3 a = grid(), b = grid(), c = grid();
    const PlaneSide plane(a, b, c);
    for (int q = 0; q < 20; ++q) {
      // Integer combinations a + s (b - a) + r (c - a): exactly coplanar
      // (every value a small multiple of 2^e), then one ulp off on an axis.
      const double s = k(), r = k();
      Vec3 d = a + s * (b - a) + r * (c - a);
      if (q % 2 == 1) {
        const int axis = static_cast<int>(rng() % 3);
        axis_ref(d, axis) = (q % 4 == 1) ? next_up(axis_coord(d, axis)) : next_down(axis_coord(d, axis));
      }
      t.count(checked(plane, a, b, c, d));
    }
    for (const Vec3 v : {a, b, c, 0.5 * (a + b)}) t.count(checked(plane, a, b, c, v));
  }
  EXPECT_GT(t.zero, 2000);
  EXPECT_GT(t.positive, 1000);
  EXPECT_GT(t.negative, 1000);
}

TEST(PlaneSide, AxisPlanesCollinearTrianglesAndZeros) {
  std::mt19937_64 rng(22);
  Tally t;
  for (int trial = 0; trial < 300; ++trial) {
    const double h = uniform(rng, -3, 3);
    const int axis = static_cast<int>(rng() % 3);
    auto on_axis_plane = [&] {
      Vec3 p{uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3)};
      axis_ref(p, axis) = h;
      return p;
    };
    const Vec3 a = on_axis_plane(), b = on_axis_plane(), c = on_axis_plane();
    const PlaneSide plane(a, b, c);
    Vec3 d = on_axis_plane();
    t.count(checked(plane, a, b, c, d));
    axis_ref(d, axis) = next_up(h);
    t.count(checked(plane, a, b, c, d));
    axis_ref(d, axis) = next_down(h);
    t.count(checked(plane, a, b, c, d));
    // A point with zero coordinates, and the origin.
    t.count(checked(plane, a, b, c, {0.0, uniform(rng, -3, 3), 0.0}));
    t.count(checked(plane, a, b, c, {0.0, 0.0, 0.0}));
    // Collinear triangle (exact midpoint of grid points): every point Zero.
    const Vec3 g{1.5, -2.25, 4.0}, gh{3.5, 1.75, -2.0};
    const PlaneSide line(g, gh, 0.5 * (g + gh));
    t.count(checked(line, g, gh, 0.5 * (g + gh), a));
  }
  EXPECT_GE(t.zero, 600);  // the point on the plane and the collinear triangle, every trial
  EXPECT_GT(t.positive, 200);
  EXPECT_GT(t.negative, 200);
}

// Points with tiny coordinates (subnormal or below 2^-950: the ulp box
// corners of points on an axis plane) near planes through grid points on
// that axis plane and off it; the stage answers with one tiny coordinate.
TEST(PlaneSide, TinyCoordinates) {
  std::mt19937_64 rng(23);
  Tally t;
  int answered = 0;
  auto k = [&] { return static_cast<double>(static_cast<int>(rng() % 16) - 8); };
  const double tiny[] = {4.9e-324, -4.9e-324, 0x1p-1000, -0x1p-960, 0x1p-1022};
  for (int trial = 0; trial < 400; ++trial) {
    const int axis = static_cast<int>(rng() % 3);
    // Triangle with two vertices on the axis plane {x_axis = 0} and a third
    // on it or off it; d on that plane (E0 == 0 when d lies on the line ab or
    // the triangle lies in the axis plane) with its axis coordinate replaced
    // by a tiny value.
    auto on_plane = [&] {
      Vec3 p{k(), k(), k()};
      axis_ref(p, axis) = 0;
      return p;
    };
    const Vec3 a = on_plane(), b = on_plane();
    Vec3 c = on_plane();
    if (trial % 2 == 1) axis_ref(c, axis) = k();
    const PlaneSide plane(a, b, c);
    Vec3 d = (trial % 4 < 2) ? a + 0.5 * (b - a) : on_plane();
    axis_ref(d, axis) = tiny[static_cast<std::size_t>(trial) % 5];
    Sign s = Sign::Zero;
    answered += plane.expansion_sign(d, s);
    t.count(checked(plane, a, b, c, d));
    // Two tiny coordinates.
    Vec3 e = d;
    axis_ref(e, (axis + 1) % 3) = tiny[static_cast<std::size_t>(trial + 1) % 5];
    t.count(checked(plane, a, b, c, e));
  }
  EXPECT_GT(answered, 300);
  EXPECT_GT(t.positive, 150);
  EXPECT_GT(t.negative, 150);
}

TEST(PlaneSide, OutsideTheRangeOrient3dDecides) {
  const Vec3 a{1, 2, 3}, b{-2, 0.5, 1}, c{0.25, -1, 2};
  const PlaneSide plane(a, b, c);
  // In the range (its edges included): the stage answers.
  for (const double v : {1e-40, 1e40, 0x1p-150, 0x1p150, -0x1p150}) {
    EXPECT_TRUE(in_range(Vec3{v, 0.5, 1.5}));
    checked(plane, a, b, c, {v, 0.5, 1.5});
  }
  // Outside: orient3d decides (checked() expects the stage to refuse).
  for (const double v : {1e-60, 1e200, 0x1p-151, 0x1p151, 0x1p-949}) {
    EXPECT_FALSE(in_range(Vec3{v, 0.5, 1.5}));
    checked(plane, a, b, c, {v, 0.5, 1.5});
  }
  // A triangle outside the range: its points all go to orient3d.
  const Vec3 tiny{1e-200, 2e-200, 0}, big{1e200, 0, 3};
  const PlaneSide far(tiny, big, c);
  EXPECT_EQ(checked(far, tiny, big, c, c), Sign::Zero);
  checked(far, tiny, big, c, {1, 1, 1});
}

}  // namespace
}  // namespace pqmesh
