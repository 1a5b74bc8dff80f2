// Plane groups and crease pieces at a P vertex (square_cases.hpp
// plane_groups / crease_pieces): facets joined by flat edges at the vertex
// are one group; a vertex-box square meeting two groups, or a crease and a
// facet off it, splits into pieces only across reflex creases or when each
// piece lies beyond the other's region (beyond_region, exact).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "tet3d/squares/square_cases.hpp"

namespace pqmesh::tet3d {
namespace {

struct LPrism {
  Domain3 d = make_domain(test::l_prism_with_split_side());
  OctTree tree{RootCube<3>{{-2, -2, -2}, 4}};
  std::vector<std::int32_t> leaves = tree.leaves();
  CornerSet corners{tree, leaves};
  PointBook book;
  SquareDispatcher squares{tree, corners, d, book, nullptr};
  int facet(int marker) const {
    for (std::size_t f = 0; f < d.plc.facets.size(); ++f)
      if (d.plc.facets[f].marker == marker) return static_cast<int>(f);
    ADD_FAILURE() << "no facet with marker " << marker;
    return -1;
  }
};

TEST(SquarePlaneGroups, FacetsJoinedByAFlatEdgeAtTheVertexFormOneGroup) {
  LPrism s;
  ASSERT_EQ(s.d.plc.facets.size(), 9u);  // different markers: nothing merged
  // At (1,1,1) (vertex 9): the top, the side y = 1, and both triangles of x = 1.
  std::vector<std::vector<int>> want = {{s.facet(2)}, {s.facet(5)}, {s.facet(6), s.facet(7)}};
  for (auto& g : want) std::sort(g.begin(), g.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(s.squares.plane_groups(9), want);
  // At (1,2,0) (vertex 4) the two triangles meet at the same flat edge.
  bool joined = false;
  for (const auto& g : s.squares.plane_groups(4)) joined = joined || g.size() == 2;
  EXPECT_TRUE(joined);
  // A corner of the outer wall has three singleton groups.
  EXPECT_EQ(s.squares.plane_groups(0).size(), 3u);
}

TEST(SquarePlaneGroups, AReflexCreaseSplitsTheSquareIntoOnePiecePerGroup) {
  LPrism s;
  SquareDispatcher::Incidence m;
  m.facets = {s.facet(5), s.facet(7)};  // y = 1 and the x = 1 triangle off the reflex edge
  std::sort(m.facets.begin(), m.facets.end());
  const auto pieces = s.squares.crease_pieces(9, m);
  ASSERT_EQ(pieces.size(), 2u);
  for (const auto& piece : pieces) {
    EXPECT_EQ(piece.facets.size(), 1u);
    EXPECT_TRUE(piece.edges.empty());
  }
  EXPECT_NE(pieces[0].facets[0], pieces[1].facets[0]);
}

TEST(SquarePlaneGroups, NoPiecesAcrossAConvexCreaseOrWithinOneCrease) {
  LPrism s;
  SquareDispatcher::Incidence m;
  m.facets = {s.facet(2), s.facet(6)};  // the top meets group {6, 7} at a convex crease
  std::sort(m.facets.begin(), m.facets.end());
  EXPECT_TRUE(s.squares.crease_pieces(9, m).empty());
  m.facets = {s.facet(5), s.facet(6)};  // reflex, but a crease of the vertex in m too
  std::sort(m.facets.begin(), m.facets.end());
  for (const int e : s.squares.vertex_edges(9)) {
    const DomainEdge& de = s.d.edges[static_cast<std::size_t>(e)];
    if ((de.facets[0] == m.facets[0] && de.facets[1] == m.facets[1]) ||
        (de.facets[1] == m.facets[0] && de.facets[0] == m.facets[1]))
      m.edges = {e};
  }
  ASSERT_EQ(m.edges.size(), 1u);
  EXPECT_TRUE(s.squares.crease_pieces(9, m).empty());
  m = {};
  m.facets = {s.facet(3), s.facet(4)};  // at vertex 1 = (2,0,0) they meet in a convex crease
  std::sort(m.facets.begin(), m.facets.end());
  EXPECT_TRUE(s.squares.crease_pieces(1, m).empty());
}

// A box whose top holds a pit shaped like a four-pointed star pyramid, apex
// (0, 0, -1) under the star's centre, tips at distance 2 and inner corners
// at (±1/8, ±1/8). At the apex the pit's creases to the tips are reflex
// for P (the star pyramid's convex edges) and those to the inner corners
// convex. Side k (facet 6 + k) is the triangle on star edge k -> k + 1,
// star corners alternating tip, inner corner from the tip on +x.
struct StarPit {
  static Plc3 plc() {
    Plc3 p;
    for (const double z : {-2.0, 0.0})
      for (const auto& c : std::vector<std::array<double, 2>>{{-3, -3}, {3, -3}, {3, 3}, {-3, 3}})
        p.vertices.push_back({c[0], c[1], z});
    const double r = 0.125;
    const std::vector<std::array<double, 2>> star = {{2, 0}, {r, r}, {0, 2}, {-r, r}, {-2, 0}, {-r, -r}, {0, -2}, {r, -r}};
    for (const auto& c : star) p.vertices.push_back({c[0], c[1], 0});
    p.vertices.push_back({0, 0, -1});  // the apex, vertex 16
    const std::vector<std::vector<int>> box = {{0, 3, 2, 1}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (const auto& loop : box) p.facets.push_back(Facet3{{loop}, static_cast<int>(p.facets.size()) + 1});
    p.facets.push_back(Facet3{{{4, 5, 6, 7}, {8, 9, 10, 11, 12, 13, 14, 15}}, 6});
    for (int k = 0; k < 8; ++k)
      p.facets.push_back(Facet3{{{8 + k, 16, 8 + (k + 1) % 8}}, 7 + k});
    return p;
  }
  static constexpr int kApex = 16;
  Domain3 d = make_domain(plc());
  OctTree tree{RootCube<3>{{-4, -4, -4}, 8}};
  std::vector<std::int32_t> leaves = tree.leaves();
  CornerSet corners{tree, leaves};
  PointBook book;
  SquareDispatcher squares{tree, corners, d, book, nullptr};
  int side(int k) const { return 6 + k; }
  int edge(int f, int g) const {
    for (std::size_t e = 0; e < d.edges.size(); ++e)
      if ((d.edges[e].facets[0] == f && d.edges[e].facets[1] == g) ||
          (d.edges[e].facets[0] == g && d.edges[e].facets[1] == f))
        return static_cast<int>(e);
    ADD_FAILURE() << "no edge between facets " << f << " and " << g;
    return -1;
  }
};

TEST(SquarePlaneGroups, ACreaseThroughTheSquareJoinsItsFacetsIntoOnePiece) {
  StarPit s;
  ASSERT_EQ(s.d.plc.facets.size(), 14u);
  ASSERT_EQ(s.squares.vertex_facets(StarPit::kApex).size(), 8u);
  // Sides 0 and 1 meet in the convex crease to inner corner 1, which crosses
  // the square; side 2 lies across the reflex crease to tip 2.
  SquareDispatcher::Incidence m;
  m.facets = {s.side(0), s.side(1), s.side(2)};
  m.edges = {s.edge(s.side(0), s.side(1))};
  const auto pieces = s.squares.crease_pieces(StarPit::kApex, m);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].facets, (std::vector<int>{s.side(0), s.side(1)}));
  EXPECT_EQ(pieces[0].edges, m.edges);
  EXPECT_EQ(pieces[1].facets, std::vector<int>{s.side(2)});
  EXPECT_TRUE(pieces[1].edges.empty());
  // Without the crease in m, sides 0 and 1 meet only in that convex crease.
  m.edges.clear();
  m.facets = {s.side(0), s.side(1)};
  EXPECT_TRUE(s.squares.crease_pieces(StarPit::kApex, m).empty());
}

TEST(SquarePlaneGroups, FacetsApartByTheirExactSidesArePieces) {
  StarPit s;
  // Sides 0 and 3 share no edge. Side 0 spans the apex, (2,0,0) and
  // (1/8,1/8,0): normal n = (2,0,1) x (1/8,1/8,1) = (-1/8, -15/8, 1/4), with
  // n . (w - apex) = 1/8 > 0 at the pit's inner point w = (0,0,-1/2), so
  // positive is beyond. Side 3's corners (-1/8,1/8,0) and (-2,0,0) give
  // 1/32 and 1/2: beyond. Side 3 is side 0 mirrored in x = 0, so side 0 is
  // beyond side 3 as well. Side 1's corner (0,2,0) gives -7/2: not beyond.
  SquareDispatcher::Incidence a, b;
  a.facets = {s.side(0)};
  b.facets = {s.side(3)};
  EXPECT_TRUE(s.squares.beyond_region(StarPit::kApex, a, b));
  EXPECT_TRUE(s.squares.beyond_region(StarPit::kApex, b, a));
  SquareDispatcher::Incidence m;
  m.facets = {s.side(0), s.side(3)};
  EXPECT_EQ(s.squares.crease_pieces(StarPit::kApex, m).size(), 2u);
  // Side 1 (adjacent to side 0 in a convex crease) is not beyond side 0.
  b.facets = {s.side(1)};
  EXPECT_FALSE(s.squares.beyond_region(StarPit::kApex, b, a));
}

}  // namespace
}  // namespace pqmesh::tet3d
