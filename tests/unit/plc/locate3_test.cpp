// Exact point location in 3D (locate(Domain3) and detail::DomainLocator3),
// including rays through edges, vertices and along facets.
#include <gtest/gtest.h>

#include <functional>

#include "domain_fixtures.hpp"
#include "plc/point_location.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh {
namespace {

using test::add_box;
using test::box;

// Both entry points must agree with the expectation.
void expect_location(const Domain3& d, Vec3 p, Location want) {
  EXPECT_EQ(locate(d, p), want) << p.x << " " << p.y << " " << p.z;
  EXPECT_EQ(detail::DomainLocator3(d).locate(p), want) << p.x << " " << p.y << " " << p.z;
}

TEST(Locate3, Cube) {
  const Domain3 d = make_domain(box());
  expect_location(d, {0.5, 0.5, 0.5}, Location::Inside);
  expect_location(d, {2, 0.5, 0.5}, Location::Outside);
  expect_location(d, {-1, 0.5, 0.5}, Location::Outside);
  expect_location(d, {0.5, 0.5, 1}, Location::Boundary);      // on a facet
  expect_location(d, {1, 1, 0.5}, Location::Boundary);        // on an edge
  expect_location(d, {1, 1, 1}, Location::Boundary);          // at a vertex
  expect_location(d, {0.25, 0.25, 0.75}, Location::Inside);
  // The right facet x = 1 is split by a diagonal through (1, 1/2, 1/2): the
  // +x ray from (1/4, 1/2, 1/2) hits the diagonal exactly.
  expect_location(d, {0.25, 0.5, 0.5}, Location::Inside);
  // Rays through a box vertex and along facets: y = 0 and z = 0 exactly.
  expect_location(d, {0.5, 0, 0}, Location::Boundary);
  expect_location(d, {-0.5, 0, 0}, Location::Outside);
  expect_location(d, {0.5, 1, 1}, Location::Boundary);
  expect_location(d, {0.5, std::nextafter(1.0, 2.0), 0.5}, Location::Outside);
  expect_location(d, {0.5, std::nextafter(1.0, 0.0), 0.5}, Location::Inside);
}

TEST(Locate3, OctahedronRaysThroughVertices) {
  const Domain3 d = make_domain(test::octahedron(1));
  expect_location(d, {0, 0, 0}, Location::Inside);        // the ray passes through vertex (1,0,0)
  expect_location(d, {-0.5, 0, 0}, Location::Inside);
  expect_location(d, {1, 0, 0}, Location::Boundary);      // vertex
  expect_location(d, {0, 0.5, 0.5}, Location::Boundary);  // on edge (0,1,0)-(0,0,1)
  expect_location(d, {-0.5, 0.5, 0}, Location::Boundary); // on edge (-1,0,0)-(0,1,0)
  expect_location(d, {-0.75, 0.5, 0}, Location::Outside); // the ray passes through edges (-1,0,0)-(0,1,0) ...
  expect_location(d, {0, 0.5, 0}, Location::Inside);      // ... and (1,0,0)-(0,1,0) and (0,1,0) side
  expect_location(d, {0.5, 0.5, 0.5}, Location::Outside);
}

// Dyadic grid of points checked against an exact membership oracle: many
// points lie on facets, edges, vertices, and many rays graze facets or pass
// through edges and vertices.
void sweep(const Domain3& d, Vec3 lo, Vec3 hi, double step, const std::function<Location(Vec3)>& oracle) {
  const detail::DomainLocator3 fast(d);
  int counts[3] = {0, 0, 0};
  for (double x = lo.x; x <= hi.x; x += step)
    for (double y = lo.y; y <= hi.y; y += step)
      for (double z = lo.z; z <= hi.z; z += step) {
        const Vec3 p{x, y, z};
        const Location want = oracle(p);
        ++counts[static_cast<int>(want)];
        ASSERT_EQ(fast.locate(p), want) << x << " " << y << " " << z;
        ASSERT_EQ(locate(d, p), want) << x << " " << y << " " << z;
      }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

// Location in a closed set given by its interior and closure predicates.
Location from(bool interior, bool closed) {
  return interior ? Location::Inside : (closed ? Location::Boundary : Location::Outside);
}

TEST(Locate3, LBlockGrid) {
  const Domain3 d = make_domain(test::l_block());
  auto in = [](double a, double lo, double hi) { return lo < a && a < hi; };
  auto cl = [](double a, double lo, double hi) { return lo <= a && a <= hi; };
  sweep(d, {-0.5, -0.5, -0.5}, {2.5, 2.5, 1.5}, 0.25, [&](Vec3 p) {
    const bool interior = in(p.z, 0, 1) && ((in(p.x, 0, 2) && in(p.y, 0, 1)) || (in(p.x, 0, 1) && in(p.y, 0, 2)));
    const bool closed = cl(p.z, 0, 1) && ((cl(p.x, 0, 2) && cl(p.y, 0, 1)) || (cl(p.x, 0, 1) && cl(p.y, 0, 2)));
    return from(interior, closed);
  });
}

TEST(Locate3, CubeWithCavityGrid) {
  Plc3 plc = box({0, 0, 0}, {4, 4, 4});
  add_box(plc, {1, 1, 1}, {3, 3, 2});
  const Domain3 d = make_domain(plc);
  auto in = [](Vec3 p, Vec3 lo, Vec3 hi) {
    return lo.x < p.x && p.x < hi.x && lo.y < p.y && p.y < hi.y && lo.z < p.z && p.z < hi.z;
  };
  auto cl = [](Vec3 p, Vec3 lo, Vec3 hi) {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
  };
  sweep(d, {-1, -1, -1}, {5, 5, 5}, 0.5, [&](Vec3 p) {
    const bool interior = in(p, {0, 0, 0}, {4, 4, 4}) && !cl(p, {1, 1, 1}, {3, 3, 2});
    const bool closed = cl(p, {0, 0, 0}, {4, 4, 4}) && !in(p, {1, 1, 1}, {3, 3, 2});
    return from(interior, closed);
  });
}

TEST(Locate3, ThroughHoleGrid) {
  const Domain3 d = make_domain(test::block_with_through_hole());
  auto in = [](double a, double lo, double hi) { return lo < a && a < hi; };
  auto cl = [](double a, double lo, double hi) { return lo <= a && a <= hi; };
  sweep(d, {-0.5, -0.5, -0.5}, {3.5, 3.5, 1.5}, 0.25, [&](Vec3 p) {
    const bool interior = in(p.x, 0, 3) && in(p.y, 0, 3) && in(p.z, 0, 1) && !(cl(p.x, 1, 2) && cl(p.y, 1, 2));
    const bool closed = cl(p.x, 0, 3) && cl(p.y, 0, 3) && cl(p.z, 0, 1) && !(in(p.x, 1, 2) && in(p.y, 1, 2));
    return from(interior, closed);
  });
}

}  // namespace
}  // namespace pqmesh
