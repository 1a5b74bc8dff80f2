// The extreme angles of triangle_quality and tetrahedron_quality skip the
// atan2 of angles provably neither smallest nor largest (simplex_quality.cpp,
// extreme_candidates). The reported values must be the very same doubles as
// folding all angles: checked bit for bit against that fold, written here
// from the definitions (angle_between, dihedral = pi - angle of the face area
// vectors), over seeded random shapes, octree-like shapes with right and equal
// angles, and shapes whose angles differ by a few ulps. The same for
// tetrahedron_min_dihedral, which evaluates only the smallest dihedral angle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "predicates/predicates.hpp"
#include "pqmesh/quality.hpp"
#include "quality/tetrahedron_min_dihedral.hpp"

namespace pqmesh {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

struct Extremes {
  double min, max;
};

// All six dihedral angles, folded in the order of the faces (k < l).
Extremes all_dihedrals(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const std::array<Vec3, 4> n = {cross(d - b, c - b), cross(v, w), cross(w, u), cross(u, v)};
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l) {
      const double theta = std::numbers::pi - angle_between(n[k], n[l]);
      lo = std::min(lo, theta);
      hi = std::max(hi, theta);
    }
  return {lo * kDeg, hi * kDeg};
}

Extremes all_angles(Vec2 a, Vec2 b, Vec2 c) {
  const double t[3] = {angle_between(b - a, c - a), angle_between(c - b, a - b), angle_between(a - c, b - c)};
  return {std::min({t[0], t[1], t[2]}) * kDeg, std::max({t[0], t[1], t[2]}) * kDeg};
}

// tetrahedron_min_dihedral (min only) gives the same double as well.
void expect_same_tet(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (orient3d(a, b, c, d) == Sign::Zero) {  // degenerate: 0 and 180 by definition
    EXPECT_EQ(tetrahedron_min_dihedral(a, b, c, d), 0.0);
    return;
  }
  const TetQuality q = tetrahedron_quality(a, b, c, d);
  const Extremes e = all_dihedrals(a, b, c, d);
  EXPECT_EQ(q.min_dihedral_deg, e.min);
  EXPECT_EQ(tetrahedron_min_dihedral(a, b, c, d), e.min);
  EXPECT_EQ(q.max_dihedral_deg, e.max);
}

void expect_same_triangle(Vec2 a, Vec2 b, Vec2 c) {
  if (orient2d(a, b, c) == Sign::Zero) return;
  const TriQuality q = triangle_quality(a, b, c);
  const Extremes e = all_angles(a, b, c);
  EXPECT_EQ(q.min_angle_deg, e.min);
  EXPECT_EQ(q.max_angle_deg, e.max);
}

TEST(AngleExtremes, RandomTetrahedraMatchTheFullFold) {
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {u(rng), u(rng), u(rng)};
    expect_same_tet(p[0], p[1], p[2], p[3]);
  }
}

// Corners of a 4 x 4 x 4 grid with spacing 2^-3: many right dihedral angles
// (atan2(y, 0)) and exactly equal ones, the octree mesher's common case.
TEST(AngleExtremes, GridTetrahedraMatchTheFullFold) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> g(0, 3);
  for (int i = 0; i < 20000; ++i) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {0.125 * g(rng), 0.125 * g(rng), 0.125 * g(rng)};
    expect_same_tet(p[0], p[1], p[2], p[3]);
  }
}

// A regular tetrahedron and a cube corner, their vertices moved by a few
// ulps: angles equal up to rounding, where no key is separated from another.
TEST(AngleExtremes, NearlyEqualAnglesMatchTheFullFold) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> steps(-3, 3);
  const auto jiggle = [&](double x) {
    for (int s = steps(rng); s != 0; s += s > 0 ? -1 : 1)
      x = std::nextafter(x, s > 0 ? 2.0 * std::abs(x) + 1 : -2.0 * std::abs(x) - 1);
    return x;
  };
  const std::array<std::array<Vec3, 4>, 2> shapes = {{{Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}},
                                                      {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}}};
  for (int i = 0; i < 20000; ++i) {
    std::array<Vec3, 4> p = shapes[static_cast<std::size_t>(i % 2)];
    for (Vec3& v : p) v = {jiggle(v.x), jiggle(v.y), jiggle(v.z)};
    expect_same_tet(p[0], p[1], p[2], p[3]);
    expect_same_triangle({p[0].x, p[0].y}, {p[1].x, p[1].y}, {p[2].x, p[2].y});
  }
}

// Slivers and needles: one vertex near the opposite face or edge.
TEST(AngleExtremes, FlatTetrahedraMatchTheFullFold) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0), h(-1e-9, 1e-9);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a{u(rng), u(rng), 0}, b{u(rng), u(rng), 0}, c{u(rng), u(rng), 0};
    const Vec3 d = i % 2 == 0 ? Vec3{u(rng), u(rng), h(rng)} : Vec3{a.x + h(rng), a.y + h(rng), h(rng)};
    expect_same_tet(a, b, c, d);
  }
}

// Every scale from 2^-400 to 2^400: the face area vectors' squared lengths
// (fourth powers of the coordinates) fall below 2^-500 and above 2^500, where
// the keys are NaN and every angle is computed, and in between; plus the
// regular and cube-corner shapes with one vertex moved so that two dihedral
// angles differ by about the key gap (2^-20) times a random factor in [0, 4).
TEST(AngleExtremes, ScaledAndNearGapTetrahedraMatchTheFullFold) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0), f(0.0, 4.0);
  std::uniform_int_distribution<int> scale(-400, 400);
  for (int i = 0; i < 20000; ++i) {
    const int e = scale(rng);
    std::array<Vec3, 4> p;
    if (i % 2 == 0) {
      for (Vec3& v : p) v = {std::ldexp(u(rng), e), std::ldexp(u(rng), e), std::ldexp(u(rng), e)};
    } else {
      p = i % 4 == 1 ? std::array<Vec3, 4>{Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}}
                     : std::array<Vec3, 4>{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
      p[3] = p[3] + 0x1p-20 * Vec3{f(rng), f(rng), f(rng)};
      for (Vec3& v : p) v = {std::ldexp(v.x, e), std::ldexp(v.y, e), std::ldexp(v.z, e)};
    }
    expect_same_tet(p[0], p[1], p[2], p[3]);
  }
}

TEST(AngleExtremes, RandomTrianglesMatchTheFullFold) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> g(0, 4);
  for (int i = 0; i < 20000; ++i) {
    expect_same_triangle({u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)});
    expect_same_triangle({0.25 * g(rng), 0.25 * g(rng)}, {0.25 * g(rng), 0.25 * g(rng)}, {0.25 * g(rng), 0.25 * g(rng)});
  }
}

}  // namespace
}  // namespace pqmesh
