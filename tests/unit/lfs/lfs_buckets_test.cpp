// detail::BoundaryBuckets2: the grid-accelerated point location equals
// locate(), and the box test equals a scan over all edges.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "plc/lfs2d.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

// Independent formulation: dP meets the box iff some edge does; the edge
// meets the box iff their bounding boxes overlap and the box corners are not
// all strictly on one side of the edge's line.
bool brute_meets(const Domain2& d, Vec2 p, Vec2 q) {
  const auto& P = d.pslg.vertices;
  for (const auto& loop : d.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a = P[static_cast<std::size_t>(loop[k])], b = P[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
      if (std::max(a.x, b.x) < p.x || std::min(a.x, b.x) > q.x || std::max(a.y, b.y) < p.y || std::min(a.y, b.y) > q.y)
        continue;
      const Sign s0 = orient2d(a, b, p), s1 = orient2d(a, b, {q.x, p.y}), s2 = orient2d(a, b, q),
                 s3 = orient2d(a, b, {p.x, q.y});
      const bool all_pos = s0 == Sign::Positive && s1 == s0 && s2 == s0 && s3 == s0;
      const bool all_neg = s0 == Sign::Negative && s1 == s0 && s2 == s0 && s3 == s0;
      if (!all_pos && !all_neg) return true;
    }
  return false;
}

void check(const Domain2& d, std::uint64_t seed, const std::string& what) {
  detail::BoundaryBuckets2 buckets(d);
  std::mt19937_64 rng(seed);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const double ex = d.bbox_max.x - d.bbox_min.x, ey = d.bbox_max.y - d.bbox_min.y;
  std::vector<Vec2> xs;
  const auto& P = d.pslg.vertices;
  for (int k = 0; k < 1500; ++k) xs.push_back({d.bbox_min.x + (1.2 * u() - 0.1) * ex, d.bbox_min.y + (1.2 * u() - 0.1) * ey});
  // Degenerate queries: vertices, edge midpoints (exact for dyadic inputs),
  // and points at the exact height of a vertex (the ray passes through it).
  for (const auto& loop : d.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a = P[static_cast<std::size_t>(loop[k])], b = P[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
      xs.push_back(a);
      xs.push_back(0.5 * (a + b));
      xs.push_back({d.bbox_min.x + u() * ex, a.y});
      xs.push_back({a.x - 0.25 * ex * u(), a.y});
    }
  int counts[3] = {0, 0, 0};
  for (Vec2 x : xs) {
    const Location want = locate(d, x);
    ++counts[static_cast<int>(want)];
    EXPECT_EQ(buckets.where(x), want) << what << " at (" << x.x << ", " << x.y << ")";
  }
  EXPECT_GT(counts[0], 0) << what;  // some of each kind were tested
  EXPECT_GT(counts[1], 0) << what;
  EXPECT_GT(counts[2], 0) << what;
  for (int k = 0; k < 1500; ++k) {
    const Vec2 c{d.bbox_min.x + u() * ex, d.bbox_min.y + u() * ey};
    const double h = std::ldexp(ex, -static_cast<int>(rng() % 8));
    const Vec2 p{c.x - h * u(), c.y - h * u()}, q{p.x + h, p.y + h};
    EXPECT_EQ(buckets.box_meets_boundary(p, q), brute_meets(d, p, q)) << what;
  }
}

TEST(LfsBuckets, CorpusAgreesWithLocate) {
  for (const char* name : {"square", "square_holes", "l_shape", "comb", "regions", "spike_1deg"})
    check(make_domain(read_pslg(test::data_path(std::string("2d/") + name + ".poly"))), 3, name);
}

TEST(LfsBuckets, RandomPolygonsAgreeWithLocate) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed)
    check(make_domain(test::random_polygon_with_holes(seed)), seed, test::describe_polygon(seed));
}

}  // namespace
}  // namespace pqmesh
