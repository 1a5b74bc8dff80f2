// §4.4 Case C on single box-face squares (cut_square.hpp): random slanted
// facets through random octrees of the unit cube. For every face square of
// every leaf, the triangles of π = S ∩ (P's side of F) must
//   * be counter-clockwise about +n (exact orient2d on the projection),
//   * have every vertex exactly on S's plane, in the closed square, and on
//     P's side of F or within an ulp of F's plane,
//   * have total area equal to the area of S ∩ half-plane, computed here
//     independently by clipping the square's corners (relative 1e-9),
// and triangulating the same square twice into one PointBook (the two boxes
// sharing it) must give the same triangles, with no new vertex.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "predicates/predicates.hpp"
#include "square_test_util.hpp"
#include "tet3d/squares/cut_square.hpp"

namespace pqmesh::tet3d {
namespace {

using test::coord;

// A large tetrahedron whose facet 0 spans the plane through a, b, c (with P
// on the side of `inside`).
Domain3 tetra_domain(Vec3 a, Vec3 b, Vec3 c, Vec3 inside) {
  Plc3 plc;
  plc.vertices = {a, b, c, inside};
  const int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  for (const auto& f : faces) {
    Facet3 fc;
    fc.loops.push_back({f[0], f[1], f[2]});
    plc.facets.push_back(fc);
  }
  return make_domain(plc);
}

double dyadic(std::mt19937_64& rng, double lo, double hi) {
  const double u = static_cast<double>(rng() >> 40) / static_cast<double>(std::uint64_t{1} << 24);
  return lo + (hi - lo) * u;
}

// Area of the part of the square (corners q[0..3], CCW about +n) on the
// non-positive side of the plane, by Sutherland-Hodgman clipping in (u, v).
double clipped_area(const std::array<Vec3, 4>& q, const FacetPlane& plane, int u, int v) {
  std::vector<Vec3> poly;
  for (int i = 0; i < 4; ++i) {
    const Vec3 p = q[static_cast<std::size_t>(i)], r = q[static_cast<std::size_t>((i + 1) % 4)];
    const double dp = plane.distance(p), dr = plane.distance(r);
    if (dp <= 0) poly.push_back(p);
    if ((dp < 0 && dr > 0) || (dp > 0 && dr < 0)) poly.push_back(p + (dp / (dp - dr)) * (r - p));
  }
  double area = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec3& p = poly[i];
    const Vec3& r = poly[(i + 1) % poly.size()];
    area += coord(p, u) * coord(r, v) - coord(r, u) * coord(p, v);
  }
  return area / 2;
}

TEST(CutSquare, RandomFacetsThroughRandomTrees) {
  std::map<CutCase, int> cases;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    const OctTree t = test::random_tree(rng);
    const std::vector<std::int32_t> leaves = t.leaves();
    const CornerSet corners(t, leaves);
    const Vec3 a{dyadic(rng, -0.5, 1.5), dyadic(rng, -0.5, 1.5), dyadic(rng, -1, 0.2)};
    const Vec3 b{dyadic(rng, -0.5, 1.5), dyadic(rng, -0.5, 1.5), dyadic(rng, 0.8, 2)};
    const Vec3 c{dyadic(rng, -0.5, 1.5), dyadic(rng, -0.5, 1.5), dyadic(rng, -1, 2)};
    const Vec3 n = cross(b - a, c - a);
    const double len = norm(n);
    if (len < 0.1) continue;
    const Vec3 inside = a + (8.0 / len) * n;  // far to one side: P is that side of F
    const Domain3 d = tetra_domain(a, b, c, inside);
    // make_domain orients facets outward; find the facet spanning a, b, c.
    int f0 = -1;
    for (std::size_t f = 0; f < d.plc.facets.size(); ++f) {
      const auto& loop = d.plc.facets[f].loops[0];
      if (std::find(loop.begin(), loop.end(), 3) == loop.end()) f0 = static_cast<int>(f);
    }
    ASSERT_GE(f0, 0);
    const FacetPlane plane(d, f0);
    PointBook book;
    for (const std::int32_t leaf : leaves)
      for (int axis = 0; axis < 3; ++axis)
        for (const bool upper : {false, true}) {
          std::vector<FaceSquare> squares;
          face_squares(t.key(leaf), axis, upper, corners, squares);
          for (const FaceSquare& s : squares) {
            std::vector<std::array<int, 3>> tris, again;
            const CutCase cc = triangulate_cut_square(s, corners, t, plane, book, tris);
            ++cases[cc];
            const int before = book.size();
            triangulate_cut_square(s, corners, t, plane, book, again);
            EXPECT_EQ(tris, again);
            EXPECT_EQ(book.size(), before);
            const std::array<Vec3, 4> q = test::square_corners(t, s);
            double area = 0;
            for (const auto& tri : tris) {
              const Vec3 p0 = book.point(tri[0]), p1 = book.point(tri[1]), p2 = book.point(tri[2]);
              EXPECT_EQ(orient2d_projected(p0, p1, p2, s.n), Sign::Positive) << "seed " << seed;
              for (const int id : tri) {
                const Vec3 p = book.point(id);
                EXPECT_TRUE(test::on_closed_square(p, q, s)) << "seed " << seed;
                EXPECT_TRUE(plane.side(p) != Sign::Positive || within_ulp_of_plane(p, a, b, c)) << "seed " << seed;
              }
              area += test::uv_area(p0, p1, p2, s.u, s.v);
            }
            const double expected = clipped_area(q, plane, s.u, s.v);
            EXPECT_NEAR(area, expected, 1e-9 * coord(q[2] - q[0], s.u) * coord(q[2] - q[0], s.u)) << "seed " << seed;
          }
        }
  }
  for (const auto& [cc, count] : cases) std::printf("case %d: %d squares\n", static_cast<int>(cc), count);
  EXPECT_GT(cases[CutCase::C1], 0);
  EXPECT_GT(cases[CutCase::C2Inside], 0);
  EXPECT_GT(cases[CutCase::C2Outside], 0);
}

}  // namespace
}  // namespace pqmesh::tet3d
