// enclosing_radius of a tetrahedron tests the diametral ball of an edge only
// when that edge is not provably shorter than the longest one
// (simplex_quality.cpp, tet_enclosing_radius). The result must be the very
// same double as testing all six edges: checked bit for bit against that
// search, written here from the definition, over seeded random shapes, grid
// shapes (right angles, equal diagonals, coplanar and coincident points),
// few-ulp perturbations of ties, slivers and needles, and scales where the
// squared lengths underflow or overflow.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "predicates/predicates.hpp"
#include "pqmesh/quality.hpp"

namespace pqmesh {
namespace {

// Every candidate ball, every edge through the exact angle test.
double reference_enclosing_radius(const std::array<Vec3, 4>& p) {
  double best = circumradius(p[0], p[1], p[2], p[3]);
  static constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                       {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (const auto& e : kEdges)
    if (dot_sign(p[e[2]], p[e[0]], p[e[1]]) != Sign::Positive &&
        dot_sign(p[e[3]], p[e[0]], p[e[1]]) != Sign::Positive)
      best = std::min(best, 0.5 * norm(p[e[1]] - p[e[0]]));
  for (int l = 0; l < 4; ++l) {
    const Vec3 o = p[(l + 1) % 4];
    const Vec3 u = p[(l + 2) % 4] - o;
    const Vec3 v = p[(l + 3) % 4] - o;
    const Vec3 w = cross(u, v);
    const double w2 = dot(w, w);
    if (w2 == 0.0) continue;
    const Vec3 x = (1.0 / (2.0 * w2)) * cross(dot(u, u) * v - dot(v, v) * u, w);
    const double r2 = dot(x, x);
    const Vec3 d = p[l] - (o + x);
    if (std::sqrt(r2) < best && dot(d, d) <= r2 * (1.0 + 1e-10)) best = std::sqrt(r2);
  }
  return best;
}

void expect_same(std::array<Vec3, 4> p) {
  const double want = reference_enclosing_radius(p);
  const double got = enclosing_radius(p[0], p[1], p[2], p[3]);
  EXPECT_TRUE(got == want || (std::isnan(got) && std::isnan(want)))
      << got << " vs " << want << " at (" << p[0].x << " " << p[0].y << " " << p[0].z << ") ...";
}

Vec3 scaled(Vec3 v, double s) { return {v.x * s, v.y * s, v.z * s}; }

TEST(EnclosingRadiusFilter, RandomTetrahedraMatchTheFullSearch) {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50000; ++i) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {u(rng), u(rng), u(rng)};
    expect_same(p);
  }
}

// Corners of a 5 x 5 x 5 grid: right angles (dot products exactly 0), equal
// longest edges (ties the filter must leave to the exact test), coplanar and
// coincident points; also Kuhn tetrahedra of boxes with random power-of-two
// sides, the octree mesher's common case.
TEST(EnclosingRadiusFilter, GridTetrahedraMatchTheFullSearch) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int> g(0, 4), e(-6, 6), perm(0, 5);
  for (int i = 0; i < 50000; ++i) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = {0.125 * g(rng), 0.125 * g(rng), 0.125 * g(rng)};
    expect_same(p);
    const double s[3] = {std::ldexp(1.0, e(rng)), std::ldexp(1.0, e(rng)), std::ldexp(1.0, e(rng))};
    static constexpr int kOrder[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const auto& o = kOrder[perm(rng)];
    double c[3] = {0, 0, 0};
    std::array<Vec3, 4> k;
    k[0] = {0, 0, 0};
    for (int j = 0; j < 3; ++j) {
      c[o[j]] = s[o[j]];
      k[static_cast<std::size_t>(j + 1)] = {c[0], c[1], c[2]};
    }
    expect_same(k);
  }
}

// A regular tetrahedron, a cube corner and a Kuhn tetrahedron moved by a few
// ulps: edge lengths equal up to rounding, where nothing is separated.
TEST(EnclosingRadiusFilter, NearlyEqualEdgesMatchTheFullSearch) {
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<int> steps(-3, 3);
  const auto jiggle = [&](double x) {
    for (int s = steps(rng); s != 0; s += s > 0 ? -1 : 1)
      x = std::nextafter(x, s > 0 ? 2.0 * std::abs(x) + 1 : -2.0 * std::abs(x) - 1);
    return x;
  };
  const std::array<std::array<Vec3, 4>, 4> shapes = {{{Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}},
                                                      {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}},
                                                      {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{1, 1, 1}},
                                                      {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}}}};
  for (int i = 0; i < 80000; ++i) {
    std::array<Vec3, 4> p = shapes[static_cast<std::size_t>(i % 4)];
    for (Vec3& v : p) v = {jiggle(v.x), jiggle(v.y), jiggle(v.z)};
    expect_same(p);
  }
}

// Slivers and needles: one vertex near the opposite face or edge, and flat
// (coplanar) quadruples whose circumradius is infinite.
TEST(EnclosingRadiusFilter, FlatTetrahedraMatchTheFullSearch) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0), h(-1e-9, 1e-9);
  for (int i = 0; i < 50000; ++i) {
    const Vec3 a{u(rng), u(rng), 0}, b{u(rng), u(rng), 0}, c{u(rng), u(rng), 0};
    const Vec3 d = i % 3 == 0   ? Vec3{u(rng), u(rng), h(rng)}
                   : i % 3 == 1 ? Vec3{a.x + h(rng), a.y + h(rng), h(rng)}
                                : Vec3{u(rng), u(rng), 0};
    expect_same({a, b, c, d});
  }
}

// Tiny and huge scales: squared lengths in the subnormal range (the filter
// must stand aside below 2^-960) and beyond DBL_MAX (infinite).
TEST(EnclosingRadiusFilter, ExtremeScalesMatchTheFullSearch) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> g(0, 2);
  const double scales[] = {0x1p-540, 0x1p-500, 0x1p-480, 0x1p-470, 0x1p-300, 0x1p300, 0x1p510, 0x1p520, 0x1p1000};
  for (int i = 0; i < 27000; ++i) {
    const double s = scales[static_cast<std::size_t>(i % 9)];
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = i % 2 == 0 ? scaled(Vec3{u(rng), u(rng), u(rng)}, s) : scaled(Vec3{1.0 * g(rng), 1.0 * g(rng), 1.0 * g(rng)}, s);
    expect_same(p);
  }
}

// The face-ball filter (simplex_quality.cpp, FaceFilter): the circumcentre
// C = (0, 0, h) at a distance h = +-2^-k (k up to 60) from the face abc (a, b,
// c on the unit circle of z = 0), d on the sphere above that face: for h < 0
// the face ball holds d and wins, for tiny h > 0 the ball misses d by less
// than the measurement slack, for larger h the circumsphere wins. The whole
// tetrahedron is moved by an offset of 2^0 .. 2^20 (coordinates far larger
// than the edges: the filter must stand aside), in random vertex order.
TEST(EnclosingRadiusFilter, CircumcentreNearAFaceMatchesTheFullSearch) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586), up(0.05, 1.0);
  std::uniform_int_distribution<int> k(0, 60), shift(0, 20), perm(0, 3);
  for (int i = 0; i < 60000; ++i) {
    std::array<Vec3, 4> p;
    for (int j = 0; j < 3; ++j) {
      const double t = angle(rng);
      p[static_cast<std::size_t>(j)] = {std::cos(t), std::sin(t), 0};
    }
    const double h = (i % 2 == 0 ? 1 : -1) * std::ldexp(1.0, -k(rng));
    Vec3 dir{u(rng), u(rng), up(rng)};
    dir = scaled(dir, 1.0 / norm(dir));
    p[3] = Vec3{0, 0, h} + scaled(dir, std::sqrt(1 + h * h));
    if (i % 3 != 0) {
      const Vec3 offset = scaled(Vec3{u(rng), u(rng), u(rng)}, std::ldexp(1.0, shift(rng)));
      for (Vec3& v : p) v = v + offset;
    }
    std::swap(p[static_cast<std::size_t>(perm(rng))], p[3]);
    expect_same(p);
  }
}

}  // namespace
}  // namespace pqmesh
