// Ear clipping with hole bridges (src/plc/facet_triangulation.hpp).
#include "plc/facet_triangulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "predicates/predicates.hpp"

namespace pqmesh::detail {
namespace {

double area(const std::vector<Vec2>& p, const std::array<int, 3>& t) {
  return 0.5 * cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
}

// Checks: every triangle strictly counter-clockwise, areas sum to `expected`,
// count = n + 2h - 2 (no Steiner points), and triangle interiors disjoint
// (sampled: each triangle's centroid lies strictly inside no other triangle).
void check(const std::vector<Vec2>& p, const std::vector<std::array<int, 3>>& tris, double expected, int n_vertices,
           int n_holes) {
  EXPECT_EQ(int(tris.size()), n_vertices + 2 * n_holes - 2);
  double sum = 0;
  for (const auto& t : tris) {
    EXPECT_EQ(orient2d(p[t[0]], p[t[1]], p[t[2]]), Sign::Positive);
    sum += area(p, t);
  }
  EXPECT_DOUBLE_EQ(sum, expected);
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Vec2 c = (1.0 / 3) * (p[tris[i][0]] + p[tris[i][1]] + p[tris[i][2]]);
    for (std::size_t j = 0; j < tris.size(); ++j) {
      if (i == j) continue;
      const auto& u = tris[j];
      const bool inside = orient2d(p[u[0]], p[u[1]], c) == Sign::Positive &&
                          orient2d(p[u[1]], p[u[2]], c) == Sign::Positive &&
                          orient2d(p[u[2]], p[u[0]], c) == Sign::Positive;
      EXPECT_FALSE(inside) << "triangles " << i << " and " << j << " overlap";
    }
  }
}

TEST(FacetTriangulation, SquareWithSquareHole) {
  // 2 x 2 square with a 1 x 1 hole: 8 triangles of total area 4 - 1 = 3.
  const std::vector<Vec2> p = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
  const auto tris = triangulate_polygon(p, {{0, 1, 2, 3}, {4, 5, 6, 7}});
  EXPECT_EQ(tris.size(), 8u);
  check(p, tris, 3.0, 8, 1);
}

TEST(FacetTriangulation, ClockwiseInputGivesCounterClockwiseTriangles) {
  const std::vector<Vec2> p = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
  check(p, triangulate_polygon(p, {{3, 2, 1, 0}, {7, 6, 5, 4}}), 3.0, 8, 1);
}

TEST(FacetTriangulation, HoleAlignedWithOuterVertices) {
  // The hole's rightmost vertex (2,1) is level with nothing, but (1,1)-(2,1)
  // lines up with the outer vertex (3,1): bridges must not run along hole sides.
  const std::vector<Vec2> p = {{0, 0}, {3, 0}, {3, 1}, {3, 3}, {0, 3}, {1, 1}, {1, 2}, {2, 2}, {2, 1}};
  check(p, triangulate_polygon(p, {{0, 1, 2, 3, 4}, {5, 6, 7, 8}}), 9.0 - 1.0, 9, 1);
}

TEST(FacetTriangulation, TwoHolesAndCollinearVertices) {
  // 6 x 2 rectangle with midpoints on the long sides (collinear vertices) and
  // two unit-square holes side by side: area 12 - 2 = 10.
  const std::vector<Vec2> p = {{0, 0}, {3, 0}, {6, 0}, {6, 2}, {3, 2}, {0, 2},
                               {1, 0.5}, {2, 0.5}, {2, 1.5}, {1, 1.5},
                               {4, 0.5}, {5, 0.5}, {5, 1.5}, {4, 1.5}};
  check(p, triangulate_polygon(p, {{0, 1, 2, 3, 4, 5}, {6, 7, 8, 9}, {10, 11, 12, 13}}), 10.0, 14, 2);
}

TEST(FacetTriangulation, Comb) {
  // A comb with 5 teeth of width 1, gaps of width 1, height 3, base height 1:
  // base 9 x 1 plus 5 teeth of 1 x 2 = 19. Many reflex vertices.
  std::vector<Vec2> p = {{0, 0}, {9, 0}};
  for (int k = 4; k >= 0; --k) {
    const double x = 2.0 * k;
    p.push_back({x + 1, 3});
    p.push_back({x, 3});
    if (k > 0) {
      p.push_back({x, 1});
      p.push_back({x - 1, 1});
    }
  }
  // (0,0) (9,0) (9,3) (8,3) (8,1) (7,1) (7,3) ... (1,3) (0,3): 20 vertices.
  ASSERT_EQ(p.size(), 20u);
  std::vector<int> loop(p.size());
  std::iota(loop.begin(), loop.end(), 0);
  check(p, triangulate_polygon(p, {loop}), 19.0, int(p.size()), 0);
}

TEST(FacetTriangulation, FacetFollowsLoopTurn) {
  // A 3D facet in the plane x = 1 with normal +x: triangles turn like the loop.
  std::vector<Vec3> v = {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}};
  Facet3 f{{{0, 1, 2, 3}}, 0};
  for (const auto& t : triangulate_facet(v, f, 0))
    EXPECT_GT(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]).x, 0);
  std::reverse(f.loops[0].begin(), f.loops[0].end());
  for (const auto& t : triangulate_facet(v, f, 0))
    EXPECT_LT(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]).x, 0);
}

}  // namespace
}  // namespace pqmesh::detail

namespace pqmesh::detail {
namespace {

// Random star-shaped polygons (radii in [2, 3] at sorted angles) with up to
// four square holes of side 1/2 on a grid inside the unit disk, in dyadic
// coordinates so the expected area is exact: shoelace of the outer loop minus
// the holes. Checks the invariants of check() above.
TEST(FacetTriangulation, RandomStarsWithHoles) {
  std::mt19937 rng(12345);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 5 + static_cast<int>(rng() % 60);
    std::vector<Vec2> p;
    std::vector<int> outer;
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * 3.141592653589793 * k / n;
      const double r = 2 + static_cast<double>(rng() % 9) / 8;  // dyadic radius
      // Round to multiples of 1/64 so area sums are exact in double.
      p.push_back({std::round(r * std::cos(angle) * 64) / 64, std::round(r * std::sin(angle) * 64) / 64});
      outer.push_back(k);
    }
    double area = 0;
    for (int k = 0; k < n; ++k) area += 0.5 * cross(p[k], p[(k + 1) % n]);
    std::vector<std::vector<int>> loops{outer};
    const Vec2 spots[4] = {{-1, -1}, {0.25, -1}, {-1, 0.25}, {0.25, 0.25}};
    const int holes = static_cast<int>(rng() % 5);
    for (int h = 0; h < holes; ++h) {
      const int o = static_cast<int>(p.size());
      const Vec2 c = spots[h];
      for (Vec2 d : {Vec2{0, 0}, Vec2{0.5, 0}, Vec2{0.5, 0.5}, Vec2{0, 0.5}}) p.push_back(c + d);
      loops.push_back({o, o + 1, o + 2, o + 3});
      area -= 0.25;
    }
    SCOPED_TRACE(trial);
    check(p, triangulate_polygon(p, loops), area, static_cast<int>(p.size()), holes);
  }
}

}  // namespace
}  // namespace pqmesh::detail
