// Edge removal (src/improve3d/edge_ring.hpp, ring_triangulation.hpp,
// flips.hpp): the dynamic program against every triangulation of small
// polygons, the ring order around an edge, and the orientation of the
// tetrahedra an edge removal makes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "improve3d/edge_ring.hpp"
#include "improve3d/ring_triangulation.hpp"
#include "predicates/predicates.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::improve3d::detail {
namespace {

constexpr double kForbidden = -std::numeric_limits<double>::infinity();

// The best least score over every triangulation of the polygon i .. j, by enumeration.
double brute_force(const RingScores& s, int i, int j) {
  if (j - i < 2) return std::numeric_limits<double>::infinity();
  double best = kForbidden;
  for (int k = i + 1; k < j; ++k)
    best = std::max(best, std::min({brute_force(s, i, k), brute_force(s, k, j), s.at(i, k, j)}));
  return best;
}

// The least score of a triangulation given as triangles, and whether they tile the polygon
// (m - 2 triangles, every side of the polygon in exactly one, every diagonal in exactly two).
double least_score(const RingScores& s, const std::vector<std::array<int, 3>>& triangles, bool& tiles) {
  const int m = s.size();
  std::vector<int> uses(static_cast<std::size_t>(m * m), 0);
  double least = std::numeric_limits<double>::infinity();
  for (const auto& [i, k, j] : triangles) {
    least = std::min(least, s.at(i, k, j));
    for (const auto& [x, y] : {std::array<int, 2>{i, k}, {k, j}, {i, j}}) ++uses[static_cast<std::size_t>(x * m + y)];
  }
  tiles = static_cast<int>(triangles.size()) == m - 2;
  for (int x = 0; x < m; ++x)
    for (int y = x + 1; y < m; ++y) {
      const bool side = y == x + 1 || (x == 0 && y == m - 1);
      const int n = uses[static_cast<std::size_t>(x * m + y)];
      tiles = tiles && (side ? n == 1 : (n == 0 || n == 2));
    }
  return least;
}

TEST(RingTriangulation, MatchesEveryTriangulationOnRandomScores) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(0, 60);
  std::bernoulli_distribution forbidden(0.2);
  for (int trial = 0; trial < 400; ++trial) {
    const int m = 3 + trial % (kMaxRingVertices - 2);
    RingScores scores(m);
    for (int i = 0; i < m; ++i)
      for (int k = i + 1; k < m; ++k)
        for (int j = k + 1; j < m; ++j) scores.set(i, k, j, forbidden(random) ? kForbidden : value(random));
    std::vector<std::array<int, 3>> triangles;
    const double best = best_ring_triangulation(scores, triangles);
    EXPECT_EQ(best, brute_force(scores, 0, m - 1)) << "trial " << trial << ", m " << m;
    if (best == kForbidden) continue;
    bool tiles = false;
    EXPECT_EQ(least_score(scores, triangles, tiles), best) << "trial " << trial;
    EXPECT_TRUE(tiles) << "trial " << trial;
  }
}

// A bipyramid: edge (a, b) on the z axis and m ring vertices on a circle, tetrahedra (a, b, r_i,
// r_i+1) positively oriented (ring order reversed if needed), shuffled ids.
struct Bipyramid {
  TetMesh3 mesh;
  int a = 0, b = 1;
};

Bipyramid bipyramid(int m, bool closed) {
  Bipyramid p;
  p.mesh.vertices = {{0, 0, 1}, {0, 0, -1}};
  const double pi = std::acos(-1.0);
  for (int i = 0; i < m; ++i) {
    const double t = (closed ? 2 * pi : pi) * i / (closed ? m : m - 1);
    p.mesh.vertices.push_back({std::cos(t), std::sin(t), 0});
  }
  const int count = closed ? m : m - 1;
  const bool flip = orient3d(p.mesh.vertices[0], p.mesh.vertices[1], p.mesh.vertices[2], p.mesh.vertices[3]) !=
                    Sign::Positive;
  for (int i = count - 1; i >= 0; --i) {  // reversed: the ring must not follow the tetrahedron order
    const int x = 2 + i, y = 2 + (i + 1) % m;
    p.mesh.tetrahedra.push_back(flip ? std::array<int, 4>{0, 1, y, x} : std::array<int, 4>{0, 1, x, y});
  }
  for (const auto& k : p.mesh.tetrahedra)
    EXPECT_EQ(orient3d(p.mesh.vertices[static_cast<std::size_t>(k[0])], p.mesh.vertices[static_cast<std::size_t>(k[1])],
                       p.mesh.vertices[static_cast<std::size_t>(k[2])], p.mesh.vertices[static_cast<std::size_t>(k[3])]),
              Sign::Positive);
  return p;
}

TEST(EdgeRing, OrderAndTheNewTetrahedraArePositive) {
  for (const bool closed : {true, false})
    for (int m = 3; m <= kMaxRingVertices; ++m) {
      const Bipyramid p = bipyramid(m, closed);
      TetrahedronQualityMemo memo;
      CollapseMesh mesh(p.mesh, {}, memo);
      std::vector<int> tets;
      mesh.tets_of(p.a, tets);
      EdgeRing ring;
      ASSERT_TRUE(gather_edge_ring(mesh, p.a, p.b, tets, kMaxRingVertices, ring)) << m;
      EXPECT_EQ(ring.closed, closed);
      ASSERT_EQ(ring.ring.size(), static_cast<std::size_t>(m)) << m;
      ASSERT_EQ(ring.tets.size(), static_cast<std::size_t>(closed ? m : m - 1)) << m;
      if (closed) {
        EXPECT_EQ(*std::min_element(ring.ring.begin(), ring.ring.end()), ring.ring[0]);
      }
      const auto point = [&](int v) { return p.mesh.vertices[static_cast<std::size_t>(v)]; };
      for (std::size_t i = 0; i < ring.tets.size(); ++i) {
        const int x = ring.ring[i], y = ring.ring[(i + 1) % ring.ring.size()];
        EXPECT_EQ(orient3d(point(p.a), point(p.b), point(x), point(y)), Sign::Positive) << m << " " << i;
        const auto& k = mesh.tet(ring.tets[i]);
        EXPECT_TRUE(std::is_permutation(k.begin(), k.end(), std::array<int, 4>{p.a, p.b, x, y}.begin()));
      }
      // Convex ring: every triangle (i, k, j), i < k < j, gives two positive tetrahedra.
      const std::vector<int>& r = ring.ring;
      for (std::size_t i = 0; i < r.size(); ++i)
        for (std::size_t k = i + 1; k < r.size(); ++k)
          for (std::size_t j = k + 1; j < r.size(); ++j) {
            EXPECT_EQ(orient3d(point(p.a), point(r[i]), point(r[k]), point(r[j])), Sign::Positive);
            EXPECT_EQ(orient3d(point(r[i]), point(r[k]), point(r[j]), point(p.b)), Sign::Positive);
          }
      EXPECT_FALSE(gather_edge_ring(mesh, p.a, p.b, tets, static_cast<int>(ring.tets.size()) - 1, ring));
    }
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
