// make_domain(Plc3) on valid inputs: orientation, shells, volume, edges.
#include <gtest/gtest.h>

#include <algorithm>

#include "domain_fixtures.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh {
namespace {

using test::add_box;
using test::box;
using test::facet_area;

// Every facet triangle turns like its facet normal (outward).
void expect_triangles_follow_normals(const Domain3& d) {
  for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
    const auto& T = d.facet_triangles[t];
    const Vec3 p = d.plc.vertices[T[0]], q = d.plc.vertices[T[1]], r = d.plc.vertices[T[2]];
    EXPECT_GT(dot(cross(q - p, r - p), d.facet_normals[d.facet_triangle_owner[t]]), 0) << "triangle " << t;
  }
}

TEST(Domain3, UnitCube) {
  const Domain3 d = make_domain(box());
  // Volume 1; 12 edges each on two facets; one exterior shell of 6 facets.
  EXPECT_EQ(d.volume, 1.0);
  ASSERT_EQ(d.edges.size(), 12u);
  for (std::size_t e = 0; e < d.edges.size(); ++e) {
    EXPECT_LT(d.edges[e].a, d.edges[e].b);
    EXPECT_LT(d.edges[e].facets[0], d.edges[e].facets[1]);
    if (e > 0) {
      EXPECT_TRUE(std::pair(d.edges[e - 1].a, d.edges[e - 1].b) < std::pair(d.edges[e].a, d.edges[e].b));
    }
  }
  ASSERT_EQ(d.shells.size(), 1u);
  EXPECT_TRUE(d.shells[0].exterior);
  EXPECT_EQ(d.shells[0].facets, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  // A quad splits into 2 triangles; facets keep their (already outward) loops.
  EXPECT_EQ(d.facet_triangles.size(), 12u);
  EXPECT_EQ(d.plc.facets[0].loops[0], (std::vector<int>{0, 2, 3, 1}));
  const Vec3 normals[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(d.facet_normals[f], normals[f]) << f;
    EXPECT_DOUBLE_EQ(facet_area(d, f), 1.0);
  }
  expect_triangles_follow_normals(d);
  EXPECT_EQ(d.bbox_min, (Vec3{0, 0, 0}));
  EXPECT_EQ(d.bbox_max, (Vec3{1, 1, 1}));
}

TEST(Domain3, ClockwiseFacetIsReoriented) {
  Plc3 plc = box();
  std::reverse(plc.facets[1].loops[0].begin(), plc.facets[1].loops[0].end());  // top given clockwise
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.facet_normals[1], (Vec3{0, 0, 1}));
  // Given {6, 7, 5, 4}; make_domain reverses it back to the outward order.
  EXPECT_EQ(d.plc.facets[1].loops[0], (std::vector<int>{4, 5, 7, 6}));
  EXPECT_EQ(d.volume, 1.0);
  expect_triangles_follow_normals(d);
}

TEST(Domain3, InsideOutCubeIsReoriented) {
  Plc3 plc;
  test::add_inverted_box(plc, {0, 0, 0}, {2, 2, 2});
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.volume, 8.0);
  EXPECT_EQ(d.facet_normals[5], (Vec3{1, 0, 0}));
  EXPECT_EQ(d.plc.facets[0].loops[0], (std::vector<int>{0, 2, 3, 1}));  // given {1, 3, 2, 0}, reversed
  expect_triangles_follow_normals(d);
}

TEST(Domain3, CubeWithCavity) {
  // Outer [0,1]^3, cavity [1/4, 3/4]^3: volume 1 - 1/8 exactly (dyadic).
  Plc3 plc = box();
  add_box(plc, {0.25, 0.25, 0.25}, {0.75, 0.75, 0.75});  // given outward: must be flipped
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.volume, 0.875);
  ASSERT_EQ(d.shells.size(), 2u);
  EXPECT_TRUE(d.shells[0].exterior);
  EXPECT_FALSE(d.shells[1].exterior);
  EXPECT_EQ(d.shells[0].facets, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(d.shells[1].facets, (std::vector<int>{6, 7, 8, 9, 10, 11}));
  // Floater normals point out of P, into the cavity: the cavity's bottom face
  // (z = 1/4) points up.
  EXPECT_EQ(d.facet_normals[6], (Vec3{0, 0, 1}));
  EXPECT_EQ(d.facet_normals[11], (Vec3{-1, 0, 0}));
  EXPECT_EQ(d.facet_normals[0], (Vec3{0, 0, -1}));
  expect_triangles_follow_normals(d);
}

TEST(Domain3, CavityListedFirst) {
  // The exterior shell is found by containment, not by input order.
  Plc3 plc;
  add_box(plc, {1, 1, 1}, {3, 3, 3});
  add_box(plc, {0, 0, 0}, {4, 4, 4});
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.volume, 64.0 - 8.0);
  ASSERT_EQ(d.shells.size(), 2u);
  EXPECT_EQ(d.shells[0].facets.front(), 6);
  EXPECT_EQ(d.shells[1].facets.front(), 0);
}

TEST(Domain3, TwoCavities) {
  Plc3 plc = box({0, 0, 0}, {4, 4, 4});
  add_box(plc, {1, 1, 1}, {2, 2, 2});
  add_box(plc, {2.5, 2.5, 2.5}, {3.5, 3.5, 3.5});
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.volume, 62.0);
  EXPECT_EQ(d.shells.size(), 3u);
}

TEST(Domain3, LBlock) {
  const Domain3 d = make_domain(test::l_block());
  EXPECT_EQ(d.volume, 3.0);  // L area 3, height 1
  EXPECT_EQ(d.edges.size(), 18u);  // 6 bottom + 6 top + 6 vertical
  // The hexagonal bottom/top split into 4 triangles each, the 6 walls into 2.
  EXPECT_EQ(d.facet_triangles.size(), 4u + 4u + 12u);
  EXPECT_DOUBLE_EQ(facet_area(d, 0), 3.0);
  EXPECT_EQ(d.facet_normals[0], (Vec3{0, 0, -1}));
  expect_triangles_follow_normals(d);
}

TEST(Domain3, ThroughHoleGenusOne) {
  const Domain3 d = make_domain(test::block_with_through_hole());
  EXPECT_EQ(d.volume, 8.0);  // 3 x 3 x 1 minus the 1 x 1 x 1 hole
  EXPECT_EQ(d.edges.size(), 24u);
  ASSERT_EQ(d.shells.size(), 1u);
  // A square with a square hole: 8 vertices, 1 hole -> 8 + 2 - 2 = 8 triangles.
  EXPECT_DOUBLE_EQ(facet_area(d, 0), 8.0);
  EXPECT_DOUBLE_EQ(facet_area(d, 1), 8.0);
  EXPECT_EQ(std::count(d.facet_triangle_owner.begin(), d.facet_triangle_owner.end(), 1), 8);
  // Inner walls face the hole axis: the wall over y = 1 points to +y.
  EXPECT_EQ(d.facet_normals[6], (Vec3{0, 1, 0}));
  expect_triangles_follow_normals(d);
}

TEST(Domain3, HoleLoopGivenWithOuterTurnIsFixed) {
  Plc3 plc = test::block_with_through_hole();
  auto& hole = plc.facets[1].loops[1];
  std::reverse(hole.begin(), hole.end());  // now turns like the outer loop
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.volume, 8.0);
  EXPECT_EQ(d.plc.facets[1].loops[1], (std::vector<int>{12, 15, 14, 13}));
  expect_triangles_follow_normals(d);
}

TEST(Domain3, OctahedronAndHolePoints) {
  Plc3 plc = test::octahedron(1);
  plc.holes = {{5, 5, 5}};  // outside: accepted
  const Domain3 d = make_domain(plc);
  EXPECT_NEAR(d.volume, 4.0 / 3.0, 1e-15);
  EXPECT_EQ(d.edges.size(), 12u);
}

TEST(Domain3, HolePointInCavityAccepted) {
  Plc3 plc = box({0, 0, 0}, {4, 4, 4});
  add_box(plc, {1, 1, 1}, {3, 3, 3});
  plc.holes = {{2, 2, 2}};
  EXPECT_NO_THROW(make_domain(plc));
}

TEST(Domain3, CoplanarAdjacentFacetsAndCollinearVertices) {
  // [0,2]^3 with the top face split at x = 1 into two coplanar facets with
  // different markers (so they stay two facets, merge_coplanar_test.cpp); the
  // front and back faces gain the split points (1,0,2), (1,2,2) as collinear
  // vertices (pentagons).
  Plc3 plc = box({0, 0, 0}, {2, 2, 2});
  plc.vertices.push_back({1, 0, 2});  // 8
  plc.vertices.push_back({1, 2, 2});  // 9
  plc.facets[1].loops[0] = {4, 8, 9, 6};
  plc.facets.push_back(Facet3{{{8, 5, 7, 9}}, 1});  // facet 6
  plc.facets[2].loops[0] = {0, 1, 5, 8, 4};
  plc.facets[3].loops[0] = {2, 6, 9, 7, 3};
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.volume, 8.0);
  EXPECT_EQ(d.edges.size(), 15u);  // 12 - 2 split edges + 4 halves + the split line (8, 9)
  EXPECT_EQ(d.facet_normals[6], (Vec3{0, 0, 1}));
  EXPECT_DOUBLE_EQ(facet_area(d, 2), 4.0);  // the pentagon is still the 2 x 2 square
  expect_triangles_follow_normals(d);
  EXPECT_EQ(locate(d, {1, 1, 2}), Location::Boundary);
  EXPECT_EQ(locate(d, {1, 1, 1}), Location::Inside);
}

TEST(Domain3, UnusedVertexIgnored) {
  Plc3 plc = box();
  plc.vertices.push_back({0, 0, 0});  // equal to vertex 0 but unused: not a duplicate
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.plc.vertices.size(), 9u);
  EXPECT_EQ(d.volume, 1.0);
}

}  // namespace
}  // namespace pqmesh
