// DomainLocator2 (banded exact point location) agrees with locate() on every
// query: random points, the polygon's own vertices, edge midpoints (exactly on
// the boundary: the generator's coordinates are dyadic) and points on the
// band boundaries.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "plc/point_location2.hpp"
#include "pqmesh/domain.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

TEST(DomainLocator2, AgreesWithLocate) {
  int boundary = 0, inside = 0, outside = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const Domain2 d = make_domain(test::random_polygon_with_holes(seed));
    const detail::DomainLocator2 locator(d);
    std::mt19937_64 rng(seed);
    const auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
    std::vector<Vec2> queries;
    for (int i = 0; i < 400; ++i)
      queries.push_back({d.bbox_min.x + (d.bbox_max.x - d.bbox_min.x) * (1.2 * unit() - 0.1),
                         d.bbox_min.y + (d.bbox_max.y - d.bbox_min.y) * (1.2 * unit() - 0.1)});
    for (const auto& s : d.pslg.segments) {
      const Vec2 a = d.pslg.vertices[static_cast<std::size_t>(s[0])], b = d.pslg.vertices[static_cast<std::size_t>(s[1])];
      queries.push_back(a);
      queries.push_back({0.5 * (a.x + b.x), 0.5 * (a.y + b.y)});
      queries.push_back({0.5 * (a.x + b.x) + 1e-9, a.y});  // on a vertex's horizontal line
    }
    for (const Vec2 q : queries) {
      const Location want = locate(d, q), got = locator.locate(q);
      ASSERT_EQ(got, want) << "seed " << seed << " at (" << q.x << ", " << q.y << ")";
      boundary += want == Location::Boundary;
      inside += want == Location::Inside;
      outside += want == Location::Outside;
    }
  }
  EXPECT_GT(boundary, 1000);
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
}

}  // namespace
}  // namespace pqmesh
