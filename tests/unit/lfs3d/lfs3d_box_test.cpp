// The exact triangle-versus-box tests of the I3 quadrature: hand cases, and
// two independent exact implementations (incidence decomposition and
// separating axes) compared on random small-integer configurations, which are
// full of degeneracies (coplanar, touching, collinear).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "plc/lfs3d.hpp"

namespace pqmesh {
namespace {

using detail::triangle_meets_box;
using detail::triangle_meets_box_sat;

TEST(Lfs3Box, HandCases) {
  const Vec3 lo{0, 0, 0}, hi{1, 1, 1};
  // A big triangle in the plane z = 0 covering the bottom face: touches the
  // closed box, misses its interior.
  const Vec3 a{-5, -5, 0}, b{5, -5, 0}, c{0, 5, 0};
  EXPECT_TRUE(triangle_meets_box(a, b, c, lo, hi));
  EXPECT_TRUE(triangle_meets_box_sat(a, b, c, lo, hi, false));
  EXPECT_FALSE(triangle_meets_box_sat(a, b, c, lo, hi, true));
  // The same triangle at z = 0.5 cuts through the box.
  const Vec3 a2{-5, -5, 0.5}, b2{5, -5, 0.5}, c2{0, 5, 0.5};
  EXPECT_TRUE(triangle_meets_box_sat(a2, b2, c2, lo, hi, true));
  EXPECT_TRUE(triangle_meets_box(a2, b2, c2, lo, hi));
  // At z = 1.5: misses.
  const Vec3 a3{-5, -5, 1.5}, b3{5, -5, 1.5}, c3{0, 5, 1.5};
  EXPECT_FALSE(triangle_meets_box(a3, b3, c3, lo, hi));
  EXPECT_FALSE(triangle_meets_box_sat(a3, b3, c3, lo, hi, false));
  // A slanted triangle passing near the corner (1,1,1): the plane x+y+z = 3
  // touches the box only at that corner; x+y+z = 3.5 misses it, 2.5 cuts it.
  for (double s : {2.5, 3.0, 3.5}) {
    const Vec3 p{s, 0, 0}, q{0, s, 0}, r{0, 0, s};
    const bool closed_expected = s <= 3.0, open_expected = s < 3.0;
    EXPECT_EQ(triangle_meets_box(p, q, r, lo, hi), closed_expected) << s;
    EXPECT_EQ(triangle_meets_box_sat(p, q, r, lo, hi, false), closed_expected) << s;
    EXPECT_EQ(triangle_meets_box_sat(p, q, r, lo, hi, true), open_expected) << s;
  }
  // A triangle whose plane cuts the box but which lies beside it: the corner
  // region near (2, 2, *) of the plane z = 0.5 (SAT needs a side axis here).
  const Vec3 p{1.5, 3, 0.5}, q{3, 1.5, 0.5}, r{3, 3, 0.5};
  EXPECT_FALSE(triangle_meets_box(p, q, r, lo, hi));
  EXPECT_FALSE(triangle_meets_box_sat(p, q, r, lo, hi, false));
  // With the side from (0, 2) to (2, 0) (line x + y = 2) it touches the box
  // edge {x = 1, y = 1} at z = 0.5 and nothing else: closed only.
  const Vec3 p2{0, 2, 0.5}, q2{2, 0, 0.5}, r2{3, 3, 0.5};
  EXPECT_TRUE(triangle_meets_box(p2, q2, r2, lo, hi));
  EXPECT_TRUE(triangle_meets_box_sat(p2, q2, r2, lo, hi, false));
  EXPECT_FALSE(triangle_meets_box_sat(p2, q2, r2, lo, hi, true));
}

bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = cross(b - a, c - a);  // exact for small integers
  return n.x == 0 && n.y == 0 && n.z == 0;
}

// Random triangles with coordinates in {-2..6} against boxes with integer
// corners in [0, 4]: the decomposition and SAT agree on the closed box; the
// open box meets T exactly when the closed box shrunk by 2^-20 does (for such
// small integers a point of T in the open box can be found at depth far above
// 2^-20: the centroid of the corners of T cap box).
TEST(Lfs3Box, TwoExactTestsAgree) {
  std::mt19937_64 rng(1);
  auto ri = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  int met = 0, missed = 0, touching = 0;
  for (int it = 0; it < 200000; ++it) {
    Vec3 lo{double(ri(0, 3)), double(ri(0, 3)), double(ri(0, 3))};
    Vec3 hi{lo.x + ri(1, 2), lo.y + ri(1, 2), lo.z + ri(1, 2)};
    Vec3 t[3];
    for (auto& v : t) v = {double(ri(-2, 6)), double(ri(-2, 6)), double(ri(-2, 6))};
    if (it % 3 == 0) t[1].z = t[0].z, t[2].z = t[0].z;  // axis-parallel planes: many coplanar contacts
    if (collinear(t[0], t[1], t[2])) continue;
    const bool closed = triangle_meets_box_sat(t[0], t[1], t[2], lo, hi, false);
    ASSERT_EQ(closed, triangle_meets_box(t[0], t[1], t[2], lo, hi)) << it;
    const double d = 0x1.0p-20;
    const Vec3 slo{lo.x + d, lo.y + d, lo.z + d}, shi{hi.x - d, hi.y - d, hi.z - d};
    const bool open = triangle_meets_box_sat(t[0], t[1], t[2], lo, hi, true);
    ASSERT_EQ(open, triangle_meets_box(t[0], t[1], t[2], slo, shi)) << it;
    met += open;
    missed += !closed;
    touching += closed && !open;
  }
  std::printf("triangle/box: %d meet the interior, %d only touch, %d miss\n", met, touching, missed);
  EXPECT_GT(touching, 1000);
  EXPECT_GT(met, 1000);
  EXPECT_GT(missed, 1000);
}

}  // namespace
}  // namespace pqmesh
