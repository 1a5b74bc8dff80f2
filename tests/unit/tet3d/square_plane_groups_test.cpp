// Plane groups at a P vertex (square_cases.hpp plane_groups /
// plane_group_pieces): facets joined by flat edges at the vertex are one
// group, and a vertex-box square meeting two groups splits into one piece
// per group only across a reflex crease.
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
  const auto pieces = s.squares.plane_group_pieces(9, m);
  ASSERT_EQ(pieces.size(), 2u);
  for (const auto& piece : pieces) {
    EXPECT_EQ(piece.facets.size(), 1u);
    EXPECT_TRUE(piece.edges.empty());
  }
  EXPECT_NE(pieces[0].facets[0], pieces[1].facets[0]);
}

TEST(SquarePlaneGroups, NoPiecesAcrossAConvexCreaseOrAtAVertexWithoutFlatEdges) {
  LPrism s;
  SquareDispatcher::Incidence m;
  m.facets = {s.facet(2), s.facet(6)};  // the top meets group {6, 7} at a convex crease
  std::sort(m.facets.begin(), m.facets.end());
  EXPECT_TRUE(s.squares.plane_group_pieces(9, m).empty());
  m.facets = {s.facet(5), s.facet(6)};  // reflex, but a crease of the vertex in m too
  std::sort(m.facets.begin(), m.facets.end());
  for (const int e : s.squares.vertex_edges(9)) {
    const DomainEdge& de = s.d.edges[static_cast<std::size_t>(e)];
    if ((de.facets[0] == m.facets[0] && de.facets[1] == m.facets[1]) ||
        (de.facets[1] == m.facets[0] && de.facets[0] == m.facets[1]))
      m.edges = {e};
  }
  ASSERT_EQ(m.edges.size(), 1u);
  EXPECT_TRUE(s.squares.plane_group_pieces(9, m).empty());
  m = {};
  m.facets = {s.facet(3), s.facet(4)};  // vertex 1 = (2,0,0) has no flat edge
  std::sort(m.facets.begin(), m.facets.end());
  EXPECT_TRUE(s.squares.plane_group_pieces(1, m).empty());
}

}  // namespace
}  // namespace pqmesh::tet3d
