// Properties of the tetrahedron measures over seeded random tetrahedra.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "pqmesh/quality.hpp"

namespace pqmesh {
namespace {

std::array<Vec3, 4> random_tet(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<Vec3, 4> p;
  for (Vec3& v : p) v = {u(rng), u(rng), u(rng)};
  return p;
}

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

// The measures are similarity invariants: x -> 1000 x + t changes none of them
// (the volume scales by 1e9). Tetrahedra with aspect ratio above 1e4 are left
// out because there rounding in the input coordinates alone (1000 x is not
// exact) moves the measures by more than 1e-9 relative: the condition number
// grows with the aspect ratio.
TEST(RandomTetrahedra, ScaleAndTranslationInvariant) {
  std::mt19937_64 rng(20240611);
  const Vec3 t{12.5, -7.25, 3.0};
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto p = random_tet(rng);
    const TetQuality q = tetrahedron_quality(p[0], p[1], p[2], p[3]);
    if (!(q.aspect_ratio < 1e4)) continue;
    ++checked;
    const TetQuality s = tetrahedron_quality(1000.0 * p[0] + t, 1000.0 * p[1] + t, 1000.0 * p[2] + t,
                                             1000.0 * p[3] + t);
    EXPECT_LT(rel(q.aspect_ratio, s.aspect_ratio), 1e-9) << i;
    EXPECT_LT(rel(q.sphere_ratio, s.sphere_ratio), 1e-9) << i;
    EXPECT_LT(rel(q.radius_edge, s.radius_edge), 1e-9) << i;
    EXPECT_LT(rel(q.min_dihedral_deg, s.min_dihedral_deg), 1e-9) << i;
    EXPECT_LT(rel(q.max_dihedral_deg, s.max_dihedral_deg), 1e-9) << i;
    EXPECT_LT(rel(q.volume * 1e9, s.volume), 1e-9) << i;
  }
  EXPECT_GT(checked, 1900);  // the filter must not hollow out the test
}

// Bounds that hold for every tetrahedron:
//  * R_enc >= 3 r. Proof: the centre c of the minimal ball lies in the
//    tetrahedron (it is in the hull of its support points); with barycentric
//    coordinates l_i = h_i / H_i (h_i its distance to face i, H_i the height of
//    vertex i), |v_i - c| >= H_i - h_i, so R >= H_i (1 - l_i) for each i; and
//    1/r = sum 1/H_i (from r = 3V/S and A_i = 3V/H_i) >= sum (1 - l_i)/R = 3/R.
//    So aspect >= 3 (up to rounding: allow 1e-12 relative).
//  * R >= R_enc (the circumball encloses the tetrahedron), so sphere ratio >=
//    aspect ratio, and the code guarantees it exactly (same double value).
//  * R_enc >= half the longest edge (a ball holding both ends of a segment).
//  * dihedral angles in (0, 180); the six dihedrals of a tetrahedron sum to
//    between 360 and 540 degrees, so min <= 90 and max >= 60.
TEST(RandomTetrahedra, Bounds) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 5000; ++i) {
    const auto p = random_tet(rng);
    const TetQuality q = tetrahedron_quality(p[0], p[1], p[2], p[3]);
    ASSERT_NE(q.volume, 0.0);
    EXPECT_GE(q.aspect_ratio, 3.0 * (1 - 1e-12)) << i;
    EXPECT_GE(q.sphere_ratio, q.aspect_ratio) << i;
    const double renc = enclosing_radius(p[0], p[1], p[2], p[3]);
    double longest = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) longest = std::max(longest, norm(p[a] - p[b]));
    EXPECT_GE(renc, 0.5 * longest * (1 - 1e-12)) << i;
    EXPECT_LE(renc, circumradius(p[0], p[1], p[2], p[3])) << i;
    EXPECT_GT(q.min_dihedral_deg, 0.0);
    EXPECT_LE(q.min_dihedral_deg, 90.0);
    EXPECT_GE(q.max_dihedral_deg, 60.0);
    EXPECT_LT(q.max_dihedral_deg, 180.0);
  }
}

// The enclosing radius against an independent approximation: the Badoiu-
// Clarkson iteration (move the centre 1/(k+1) of the way to the farthest
// point) converges to the minimal ball's centre; the radius of the ball it
// finds, max_i |p_i - c|, encloses all points by construction, so it can never
// be smaller than the true minimum (our value must be <= it), and after 2e5
// steps it is within well under 1% of the minimum (our value must be >= 0.99
// times it). Random tetrahedra have R_enc < R often by more than 1%, so
// returning the circumradius, or a too-small ball, would fail.
TEST(RandomTetrahedra, EnclosingRadiusMatchesIterativeOracle) {
  std::mt19937_64 rng(99);
  int smaller_than_circumradius = 0;
  for (int i = 0; i < 40; ++i) {
    const auto p = random_tet(rng);
    Vec3 c = p[0];
    double radius = 0;
    for (int k = 1; k <= 200000; ++k) {
      int far = 0;
      double far2 = -1;
      for (int j = 0; j < 4; ++j) {
        const double d2 = dot(p[j] - c, p[j] - c);
        if (d2 > far2) far2 = d2, far = j;
      }
      c = c + (1.0 / (k + 1)) * (p[far] - c);
    }
    for (const Vec3& v : p) radius = std::max(radius, norm(v - c));
    const double renc = enclosing_radius(p[0], p[1], p[2], p[3]);
    EXPECT_LE(renc, radius * (1 + 1e-12)) << i;
    EXPECT_GE(renc, 0.99 * radius) << i;
    if (renc < 0.95 * circumradius(p[0], p[1], p[2], p[3])) ++smaller_than_circumradius;
  }
  EXPECT_GT(smaller_than_circumradius, 5);  // the sample exercises edge and face balls
}

// Triangles: the same similarity invariance and bounds (R_enc >= 2r by the
// argument above with 2 + 1 vertices; sphere >= aspect), and the three angles
// add up to 180 so min <= 60 <= max.
TEST(RandomTriangles, InvarianceAndBounds) {
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec2 t{-3.5, 8.25};
  for (int i = 0; i < 5000; ++i) {
    const Vec2 a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)};
    const TriQuality q = triangle_quality(a, b, c);
    ASSERT_NE(q.area, 0.0);
    EXPECT_GE(q.aspect_ratio, 2.0 * (1 - 1e-12)) << i;
    EXPECT_GE(q.sphere_ratio, q.aspect_ratio) << i;
    EXPECT_LE(q.min_angle_deg, 60.0 + 1e-9) << i;
    EXPECT_GE(q.max_angle_deg, 60.0 - 1e-9) << i;
    if (!(q.aspect_ratio < 1e4)) continue;  // conditioning, as for tetrahedra
    const TriQuality s = triangle_quality(1000.0 * a + t, 1000.0 * b + t, 1000.0 * c + t);
    EXPECT_LT(rel(q.aspect_ratio, s.aspect_ratio), 1e-9) << i;
    EXPECT_LT(rel(q.sphere_ratio, s.sphere_ratio), 1e-9) << i;
    EXPECT_LT(rel(q.radius_edge, s.radius_edge), 1e-9) << i;
    EXPECT_LT(rel(q.min_angle_deg, s.min_angle_deg), 1e-9) << i;
    EXPECT_LT(rel(q.area * 1e6, s.area), 1e-9) << i;
  }
}

}  // namespace
}  // namespace pqmesh
