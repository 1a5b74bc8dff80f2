// make_domain's last stage (plc/merge_coplanar.hpp): coplanar neighbours with
// equal markers become one facet; every input vertex stays on a facet loop.
// Expected edge counts follow from Euler's formula for one closed shell of
// genus g: a facet with one hole is an annulus (Euler characteristic 0), so
// V - E + (F - H) = 2 - 2g, E = V + F - H - 2 + 2g with H facet holes.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "domain_fixtures.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh {
namespace {

std::set<int> loop_set(const std::vector<int>& loop) { return {loop.begin(), loop.end()}; }

// Every vertex of the PLC lies on some facet loop.
void expect_every_vertex_on_a_loop(const Domain3& d) {
  std::vector<char> on(d.plc.vertices.size(), 0);
  for (const Facet3& f : d.plc.facets)
    for (const auto& loop : f.loops)
      for (const int v : loop) on[static_cast<std::size_t>(v)] = 1;
  for (std::size_t v = 0; v < on.size(); ++v) EXPECT_TRUE(on[v]) << "vertex " << v << " is on no facet";
}

TEST(MergeCoplanar, RingCapsBecomeAnnuli) {
  // Each cap: four trapezoids with one marker, joined by the four flat
  // diagonals (k, 4 + k) (bottom) and (8 + k, 12 + k) (top). Merged, the
  // domain is block_with_through_hole(): V 16, F 10, H 2, g 1:
  // E = 16 + 10 - 2 - 2 + 2 = 24, the 32 edges of the pieces minus the 8
  // diagonals.
  const Domain3 pieces = make_domain(test::block_with_through_hole_in_pieces({1, 1, 1, 1}, {2, 2, 2, 2}, 3));
  const Domain3 whole = make_domain(test::block_with_through_hole());
  ASSERT_EQ(pieces.plc.facets.size(), 10u);
  EXPECT_EQ(pieces.edges.size(), whole.edges.size());
  EXPECT_EQ(pieces.edges.size(), 24u);
  EXPECT_EQ(pieces.volume, 8.0);
  // The merged bottom takes the place of trapezoid 0, the top of trapezoid 4
  // (now id 1), walls follow in order.
  const Facet3& bottom = pieces.plc.facets[0];
  const Facet3& top = pieces.plc.facets[1];
  EXPECT_EQ(bottom.marker, 1);
  EXPECT_EQ(top.marker, 2);
  for (std::size_t f = 2; f < 10; ++f) EXPECT_EQ(pieces.plc.facets[f].marker, 3);
  ASSERT_EQ(bottom.loops.size(), 2u);
  ASSERT_EQ(top.loops.size(), 2u);
  // loops[0] holds the lexicographically smallest vertex: (0, 0, 0) below, (0, 0, 1) above.
  EXPECT_EQ(loop_set(bottom.loops[0]), (std::set<int>{0, 1, 2, 3}));
  EXPECT_EQ(loop_set(bottom.loops[1]), (std::set<int>{4, 5, 6, 7}));
  EXPECT_EQ(loop_set(top.loops[0]), (std::set<int>{8, 9, 10, 11}));
  EXPECT_EQ(loop_set(top.loops[1]), (std::set<int>{12, 13, 14, 15}));
  EXPECT_DOUBLE_EQ(test::facet_area(pieces, 0), 8.0);  // 3 x 3 minus 1 x 1
  EXPECT_EQ(pieces.facet_normals[0], (Vec3{0, 0, -1}));
  EXPECT_EQ(pieces.facet_normals[1], (Vec3{0, 0, 1}));
  // The file line of a merged facet is its first piece's.
  Plc3 lined = test::block_with_through_hole_in_pieces({1, 1, 1, 1}, {2, 2, 2, 2}, 3);
  for (int f = 0; f < 16; ++f) lined.source.element_line.push_back(100 + f);
  const Domain3 with_lines = make_domain(lined);
  ASSERT_EQ(with_lines.plc.source.element_line.size(), 10u);
  EXPECT_EQ(with_lines.plc.source.element_line[0], 100);
  EXPECT_EQ(with_lines.plc.source.element_line[1], 104);
  EXPECT_EQ(with_lines.plc.source.element_line[2], 108);
}

TEST(MergeCoplanar, DifferentMarkersStaySeparate) {
  // Bottom markers 1 1 2 2: trapezoids 0 + 1 and 2 + 3 merge (diagonals (1, 5)
  // and (3, 7) vanish), the diagonals (2, 6) and (0, 4) between markers stay;
  // the top merges whole (4 diagonals vanish): 16 - 2 - 3 = 11 facets,
  // 32 - 2 - 4 = 26 edges (V 16, F 11, H 1, g 1: 16 + 11 - 1 - 2 + 2).
  const Domain3 d = make_domain(test::block_with_through_hole_in_pieces({1, 1, 2, 2}, {5, 5, 5, 5}));
  EXPECT_EQ(d.plc.facets.size(), 11u);
  EXPECT_EQ(d.edges.size(), 26u);
  EXPECT_EQ(d.volume, 8.0);
  EXPECT_EQ(d.plc.facets[0].marker, 1);
  EXPECT_EQ(d.plc.facets[1].marker, 2);
  EXPECT_EQ(loop_set(d.plc.facets[0].loops[0]), (std::set<int>{0, 1, 2, 6, 5, 4}));
  expect_every_vertex_on_a_loop(d);
}

TEST(MergeCoplanar, CollinearSplitPointsStayOnTheMergedLoop) {
  // [0,2]^3 with the top split at x = 1 into two coplanar facets with one
  // marker: they merge into a hexagon that keeps the split points 8 and 9
  // (straight angles), so 6 facets and 15 - 1 = 14 edges (the split line
  // (8, 9) vanishes; the halves of the old top edges remain).
  Plc3 plc = test::box({0, 0, 0}, {2, 2, 2});
  plc.vertices.push_back({1, 0, 2});  // 8
  plc.vertices.push_back({1, 2, 2});  // 9
  plc.facets[1].loops[0] = {4, 8, 9, 6};
  plc.facets.push_back(Facet3{{{8, 5, 7, 9}}, 0});
  plc.facets[2].loops[0] = {0, 1, 5, 8, 4};
  plc.facets[3].loops[0] = {2, 6, 9, 7, 3};
  const Domain3 d = make_domain(plc);
  ASSERT_EQ(d.plc.facets.size(), 6u);
  EXPECT_EQ(d.edges.size(), 14u);
  ASSERT_EQ(d.plc.facets[1].loops.size(), 1u);
  EXPECT_EQ(loop_set(d.plc.facets[1].loops[0]), (std::set<int>{4, 8, 5, 7, 9, 6}));
  EXPECT_DOUBLE_EQ(test::facet_area(d, 1), 4.0);
  EXPECT_EQ(d.volume, 8.0);
  expect_every_vertex_on_a_loop(d);
}

TEST(MergeCoplanar, AVertexInsideTheMergedFacetKeepsTheGroupApart) {
  // The unit cube's top as four triangles around its centre (vertex 8), one
  // marker: merging would take vertex 8 off every loop, so the four stay
  // facets (9 in all) and all 12 + 4 = 16 edges stay.
  Plc3 plc = test::box();
  plc.vertices.push_back({0.5, 0.5, 1});  // 8
  const std::vector<int> ring = plc.facets[1].loops[0];  // {4, 5, 7, 6}
  plc.facets.erase(plc.facets.begin() + 1);
  for (std::size_t k = 0; k < 4; ++k) plc.facets.push_back(Facet3{{{ring[k], ring[(k + 1) % 4], 8}}, 0});
  const Domain3 d = make_domain(plc);
  EXPECT_EQ(d.plc.facets.size(), 9u);
  EXPECT_EQ(d.edges.size(), 16u);
  expect_every_vertex_on_a_loop(d);
}

TEST(MergeCoplanar, NotCoplanarNeighboursAreUntouched) {
  // The octahedron: eight triangles, no two coplanar.
  const Domain3 d = make_domain(test::octahedron(1));
  EXPECT_EQ(d.plc.facets.size(), 8u);
  EXPECT_EQ(d.edges.size(), 12u);
}

}  // namespace
}  // namespace pqmesh
