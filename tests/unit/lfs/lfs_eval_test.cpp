// LocalFeatureSize2 (grid + expanding rings) against the brute force over all
// feature pairs, and hand-derived values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "plc/lfs2d.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/lfs.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

Domain2 square() { return make_domain(read_pslg(test::data_path("2d/square.poly"))); }

// Unit square: features are the 4 corners and the 4 sides.
TEST(Lfs, UnitSquareHandValues) {
  const Domain2 d = square();
  const LocalFeatureSize2 lfs(d);
  // Centre: the 4 sides are nearest (0.5); opposite sides are disjoint -> 0.5.
  EXPECT_EQ(lfs.at({0.5, 0.5}), 0.5);
  EXPECT_EQ(local_feature_size(d, {0.5, 0.5}), 0.5);
  // (0.25, 0.5): left side 0.25, bottom/top 0.5 (disjoint from each other),
  // right 0.75; left side + anything disjoint from it (right side, corners
  // (1,0), (1,1)) is >= 0.75; bottom+top gives 0.5; corner pairs >= 0.559.
  EXPECT_EQ(lfs.at({0.25, 0.5}), 0.5);
  // (0.1, 0.1): left and bottom at 0.1 share corner (0,0); corner (0,0) at
  // 0.1414 lies on both. Next: top and right at 0.9 -> left + right = 0.9,
  // corners (1,0) and (0,1) at sqrt(0.81 + 0.01) = 0.9055 > 0.9 -> 0.9.
  EXPECT_DOUBLE_EQ(lfs.at({0.1, 0.1}), 0.9);
  // A corner: nearest non-incident features are the two far sides and the two
  // adjacent corners, all at distance 1.
  for (int v = 0; v < 4; ++v) EXPECT_EQ(lfs.at_vertex(v), 1.0) << v;
  // Outside the square at (-1, 0.5): left side at 1, corners (0,0), (0,1) at
  // sqrt(1.25) (both on the left side, and disjoint from each other) -> the
  // left side + a disjoint feature: right side (2), corners (1,*) at
  // sqrt(4.25); bottom/top at sqrt(1.25) are disjoint -> sqrt(1.25).
  EXPECT_DOUBLE_EQ(lfs.at({-1, 0.5}), std::sqrt(1.25));
}

// Brute-force nearest feature not incident on v (an independent formula for
// the value at a vertex).
double nearest_non_incident(const Domain2& d, int v) {
  double best = INFINITY;
  for (const auto& f : detail::lfs_features(d)) {
    if (f.a == v || f.b == v) continue;
    best = std::min(best, detail::lfs_dist2(d.pslg.vertices[static_cast<std::size_t>(v)], f, d.pslg.vertices));
  }
  return std::sqrt(best);
}

// Random points in the bounding box grown by 10% on every side, plus every
// vertex and every edge midpoint; fast == brute force bit for bit.
void check_against_brute_force(const Domain2& d, std::uint64_t seed, int points, const std::string& what) {
  const LocalFeatureSize2 lfs(d);
  std::mt19937_64 rng(seed);
  const double ex = d.bbox_max.x - d.bbox_min.x, ey = d.bbox_max.y - d.bbox_min.y;
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<Vec2> xs;
  for (int k = 0; k < points; ++k)
    xs.push_back({d.bbox_min.x + (1.2 * u() - 0.1) * ex, d.bbox_min.y + (1.2 * u() - 0.1) * ey});
  for (const auto& loop : d.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a = d.pslg.vertices[static_cast<std::size_t>(loop[k])];
      const Vec2 b = d.pslg.vertices[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
      xs.push_back(a);
      xs.push_back(0.5 * (a + b));
    }
  int mismatches = 0;
  for (Vec2 x : xs) {
    const double fast = lfs.at(x), slow = local_feature_size(d, x);
    if (fast != slow && ++mismatches <= 5)
      ADD_FAILURE() << what << ": at (" << x.x << ", " << x.y << ") fast " << fast << " brute " << slow;
    ASSERT_GT(slow, 0) << what;
  }
  EXPECT_EQ(mismatches, 0) << what;
  for (const auto& loop : d.loops)
    for (int v : loop) {
      const double want = nearest_non_incident(d, v);
      EXPECT_EQ(lfs.at_vertex(v), want) << what << " vertex " << v;
      EXPECT_EQ(local_feature_size(d, d.pslg.vertices[static_cast<std::size_t>(v)]), want) << what << " vertex " << v;
    }
}

TEST(Lfs, CorpusMatchesBruteForce) {
  for (const char* name : {"square", "square_holes", "l_shape", "comb", "regions", "spike_1deg", "spike_5deg",
                           "spike_10deg"}) {
    const Domain2 d = make_domain(read_pslg(test::data_path(std::string("2d/") + name + ".poly")));
    check_against_brute_force(d, 7, 3000, name);
  }
}

TEST(Lfs, RandomPolygonsMatchBruteForce) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Domain2 d = make_domain(test::random_polygon_with_holes(seed));
    check_against_brute_force(d, seed * 31 + 1, 400, test::describe_polygon(seed));
  }
}

TEST(Lfs, IsOneLipschitz) {
  // |lfs(x) - lfs(y)| <= |x - y| (up to rounding): a property of the
  // definition (each distance is 1-Lipschitz; max and min preserve it).
  const Domain2 d = make_domain(test::random_polygon_with_holes(3));
  const LocalFeatureSize2 lfs(d);
  std::mt19937_64 rng(5);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const double ex = d.bbox_max.x - d.bbox_min.x;
  for (int k = 0; k < 2000; ++k) {
    const Vec2 x{d.bbox_min.x + u() * ex, d.bbox_min.y + u() * ex};
    const Vec2 y{x.x + (u() - 0.5) * 0.01 * ex, x.y + (u() - 0.5) * 0.01 * ex};
    EXPECT_LE(std::abs(lfs.at(x) - lfs.at(y)), norm(x - y) * (1 + 1e-9) + 1e-12 * ex);
  }
}

}  // namespace
}  // namespace pqmesh
