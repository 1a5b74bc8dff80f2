// The square dispatcher (square_cases.hpp) on hand-made squares: the exact
// face incidences it acts on, the cases it delegates to, and the refusals
// (InternalError naming the square and the faces met). Whole meshes of every
// box kind, and the agreement of both sides of every shared square, are in
// all_boxes_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/plc.hpp"
#include "tet3d/squares/square_cases.hpp"
#include "tet3d/squares/square_meets.hpp"

namespace pqmesh::tet3d {
namespace {

Domain3 polyhedron(std::vector<Vec3> v, const std::vector<std::vector<int>>& facets) {
  Plc3 plc;
  plc.vertices = std::move(v);
  for (const auto& f : facets) {
    Facet3 fc;
    fc.loops = {f};
    plc.facets.push_back(fc);
  }
  return make_domain(plc);
}

// The root unit cube split once; S = the upper x face of the lowest child:
// x = 0.5, (y, z) in [0, 0.5]^2.
struct Fixture {
  OctTree tree{RootCube<3>{{0, 0, 0}, 1}};
  std::vector<std::int32_t> leaves;
  FaceSquare s;
  Fixture() {
    tree.split(0);
    leaves = tree.leaves();
    std::vector<FaceSquare> squares;
    face_squares(tree.key(leaves[0]), 0, true, CornerSet(tree, leaves), squares);
    s = squares.at(0);
  }
};

TEST(SquareMeets, SegmentsAndTrianglesByHand) {
  Fixture f;
  const SquareGeometry g = square_geometry(f.s, f.tree);
  EXPECT_EQ(g.c, 0.5);
  EXPECT_TRUE(square_contains(g, {0.5, 0.2, 0.3}));
  EXPECT_TRUE(square_contains(g, {0.5, 0.5, 0.5}));  // closed
  EXPECT_FALSE(square_contains(g, {0.5, 0.6, 0.3}));
  EXPECT_TRUE(segment_meets_square(g, {0.1, 0.2, 0.2}, {0.9, 0.3, 0.3}));
  EXPECT_FALSE(segment_meets_square(g, {0.1, 0.2, 0.2}, {0.9, 0.9, 0.3}));  // crosses x = 0.5 at y = 0.55
  EXPECT_TRUE(segment_meets_square(g, {0.1, 0.2, 0.2}, {0.9, 0.7, 0.3}));   // ... at y = 0.45
  EXPECT_FALSE(segment_meets_square(g, {0.1, 0.2, 0.2}, {0.4, 0.3, 0.3}));  // ends before the plane
  EXPECT_TRUE(segment_meets_square(g, {0.5, -1, 0.2}, {0.5, 1, 0.2}));      // in the plane, across
  // A triangle crossing the plane in a segment that passes beside the square,
  // then one whose section cuts a corner.
  EXPECT_FALSE(triangle_meets_square(g, {0.2, 0.7, 0.1}, {0.8, 0.7, 0.1}, {0.5, 0.9, 0.4}));
  EXPECT_TRUE(triangle_meets_square(g, {0.2, 0.45, 0.1}, {0.8, 0.45, 0.1}, {0.5, 0.9, 0.4}));
  // Coplanar: containing the square, disjoint from it.
  EXPECT_TRUE(triangle_meets_square(g, {0.5, -1, -1}, {0.5, 3, -1}, {0.5, -1, 3}));
  EXPECT_FALSE(triangle_meets_square(g, {0.5, 0.6, 0.6}, {0.5, 2, 0.6}, {0.5, 0.6, 2}));
  // The section of a big triangle is a line missing the square's corner region.
  EXPECT_FALSE(triangle_meets_square(g, {0, 0.9, -5}, {1, 0.9, -5}, {0.5, 0.9, 5}));
}

TEST(SquareCases, OneFacetIsCaseCAndMatchesCutSquare) {
  Fixture f;
  const CornerSet corners(f.tree, f.leaves);
  // A tetrahedron with its facet {0, 1, 2} crossing S obliquely.
  const Domain3 d = polyhedron({{-1.115, -3, -3}, {1.285, 5, -3}, {0.485, -3, 5}, {-5.1, 0.2, 0.1}},
                               {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
  int crossing = -1;
  for (std::size_t k = 0; k < d.plc.facets.size(); ++k) {
    const auto& loop = d.plc.facets[k].loops[0];
    bool has3 = false;
    for (const int v : loop) has3 = has3 || v == 3;
    if (!has3) crossing = static_cast<int>(k);
  }
  ASSERT_GE(crossing, 0);
  PointBook book;
  SquareDispatcher squares(f.tree, corners, d, book, nullptr);
  std::vector<std::array<int, 3>> got;
  EXPECT_EQ(squares.triangulate(f.s, squares.faces_of(BoxKind::Facet, crossing), got), SquareCase::C);
  PointBook book2;
  std::vector<std::array<int, 3>> want;
  triangulate_cut_square(f.s, corners, f.tree, FacetPlane(d, crossing), book2, want);
  ASSERT_EQ(got.size(), want.size());
  ASSERT_FALSE(got.empty());
  for (std::size_t i = 0; i < got.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(book.key(got[i][k]), book2.key(want[i][k]));
  // Seen from an empty box (no faces) the square is Case A: one triangle per ring segment.
  std::vector<std::array<int, 3>> whole;
  EXPECT_EQ(squares.triangulate(f.s, squares.faces_of(BoxKind::Empty, -1), whole), SquareCase::A);
  EXPECT_EQ(whole.size(), square_ring(f.s, corners).size());
}

TEST(SquareCases, RefusesAVertexInTheSquare) {
  Fixture f;
  const CornerSet corners(f.tree, f.leaves);
  const Domain3 d = polyhedron({{0.5, 0.2, 0.3}, {0.9, 0.1, 0.1}, {0.9, 0.45, 0.1}, {0.9, 0.2, 0.45}},
                               {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
  PointBook book;
  SquareDispatcher squares(f.tree, corners, d, book, nullptr);
  std::vector<std::array<int, 3>> out;
  try {
    squares.triangulate(f.s, squares.faces_of(BoxKind::Vertex, 0), out);
    FAIL() << "no InternalError";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("meets vertices {0}"), std::string::npos) << e.what();
  }
}

TEST(SquareCases, RefusesTwoFacetsWithoutACommonEdge) {
  Fixture f;
  const CornerSet corners(f.tree, f.leaves);
  // A triangular prism along y whose two caps (y = 0.1 and y = 0.4) cross S.
  const Domain3 d = polyhedron({{0.3, 0.1, 0.1}, {0.7, 0.1, 0.1}, {0.55, 0.1, 0.4}, {0.3, 0.4, 0.1}, {0.7, 0.4, 0.1},
                                {0.55, 0.4, 0.4}},
                               {{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
  std::vector<int> caps;
  for (std::size_t k = 0; k < d.plc.facets.size(); ++k)
    if (d.plc.facets[k].loops[0].size() == 3) caps.push_back(static_cast<int>(k));
  ASSERT_EQ(caps.size(), 2u);
  PointBook book;
  SquareDispatcher squares(f.tree, corners, d, book, nullptr);
  BoxFaces faces;
  faces.kind = BoxKind::Facet;  // any kind: the incidences are refused before the model is used
  faces.apex = caps[0];
  faces.facets = caps;
  std::vector<std::array<int, 3>> out;
  EXPECT_THROW(squares.triangulate(f.s, faces, out), InternalError);
  // With one cap only the square is Case C.
  faces.facets = {caps[0]};
  EXPECT_EQ(squares.triangulate(f.s, faces, out), SquareCase::C);
}

}  // namespace
}  // namespace pqmesh::tet3d

namespace pqmesh::tet3d {
namespace {

// A triangular prism along x over the right angle at (y, z) = (0.23, 0.27),
// x in [-1, 2]; its edge E0 on that line carries an extra vertex m at
// x = 0.2, so the facets F (z = 0.27) and G (y = 0.23) share two collinear
// edges, (p0, m) and (m, p1), as cube.obj's top and front do at (1, 0, 2).
// Vertex ids: p0 q0 r0 at x = -1, p1 q1 r1 at x = 2, m.
struct CollinearPrism {
  Domain3 d;
  int f = -1, g = -1, e_low = -1, e_high = -1;  // e_high = (m, p1) crosses S at x = 0.5
  CollinearPrism() {
    Plc3 plc;
    plc.vertices = {{-1, 0.23, 0.27}, {-1, 3, 0.27}, {-1, 0.23, 3}, {2, 0.23, 0.27}, {2, 3, 0.27}, {2, 0.23, 3},
                    {0.2, 0.23, 0.27}};
    const std::vector<std::vector<int>> loops = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3, 6}, {0, 6, 3, 5, 2}, {1, 2, 5, 4}};
    for (const auto& l : loops) plc.facets.push_back(Facet3{{l}, 0});
    d = make_domain(plc);
    for (std::size_t k = 0; k < d.plc.facets.size(); ++k) {
      const auto& loop = d.plc.facets[k].loops[0];
      if (loop.size() != 5) continue;
      const bool has_q = std::find(loop.begin(), loop.end(), 1) != loop.end();
      (has_q ? f : g) = static_cast<int>(k);
    }
    for (std::size_t e = 0; e < d.edges.size(); ++e) {
      if (d.edges[e].a == 0 && d.edges[e].b == 6) e_low = static_cast<int>(e);
      if (d.edges[e].a == 3 && d.edges[e].b == 6) e_high = static_cast<int>(e);
    }
  }
};

TEST(SquareCases, FacetsSharingCollinearEdgesUseTheEdgeThatCrossesTheSquare) {
  Fixture fx;
  const CornerSet corners(fx.tree, fx.leaves);
  const CollinearPrism p;
  ASSERT_GE(p.f, 0);
  ASSERT_GE(p.g, 0);
  ASSERT_GE(p.e_low, 0);
  ASSERT_GE(p.e_high, 0);
  PointBook book;
  SquareDispatcher squares(fx.tree, corners, p.d, book, nullptr);
  // Both edges lie on F and G; the representative is the smaller id, the
  // square's edge the one whose segment (x from 0.2 to 2) meets x = 0.5.
  EXPECT_EQ(squares.edge_of_facets(p.f, p.g), std::min(p.e_low, p.e_high));
  EXPECT_EQ(squares.edge_for_square(p.f, p.g, square_geometry(fx.s, fx.tree)), p.e_high);
  // What the boxes of either edge (and a two-facet box) build on S equals
  // Case B for (m, p1) alone.
  PointBook book2;
  std::vector<std::array<int, 3>> want;
  EXPECT_EQ(triangulate_edge_square(fx.s, corners, fx.tree, EdgeCone(p.d, p.e_high), book2, want), EdgeCutCase::B);
  ASSERT_FALSE(want.empty());
  for (const BoxFaces& faces : {squares.faces_of(BoxKind::Edge, p.e_high), squares.faces_of(BoxKind::Edge, p.e_low),
                                squares.faces_of(BoxKind::TwoFacet, p.e_low)}) {
    std::vector<std::array<int, 3>> got;
    EXPECT_EQ(squares.triangulate(fx.s, faces, got), SquareCase::BD);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(book.key(got[i][k]), book2.key(want[i][k]));
  }
  // The local model is the common wedge: inside near the edge on both sides of m.
  SquareDispatcher::Incidence m;
  m.facets = {std::min(p.f, p.g), std::max(p.f, p.g)};
  EXPECT_EQ(squares.local_status(m, {0.5, 0.3, 0.3}), Sign::Negative);
  EXPECT_EQ(squares.local_status(m, {-0.5, 0.3, 0.3}), Sign::Negative);
  EXPECT_EQ(squares.local_status(m, {0.5, 0.2, 0.3}), Sign::Positive);
}

// Facets meeting at a flat edge (coplanar, different markers, so not merged)
// are accepted; the local model of a square meeting both is P's side of
// their common plane z = 0 (P is z > 0 there).
TEST(SquareCases, AFlatEdgeHasTheHalfSpaceAsItsLocalModel) {
  Fixture fx;
  const CornerSet corners(fx.tree, fx.leaves);
  const Domain3 d = make_domain(test::cube_with_split_bottom());
  ASSERT_EQ(d.plc.facets.size(), 7u);  // different markers: the bottom halves stay apart
  PointBook book;
  SquareDispatcher squares(fx.tree, corners, d, book, nullptr);
  SquareDispatcher::Incidence m;
  m.facets = {0, 1};
  EXPECT_EQ(squares.local_status(m, {0.3, 0.6, 0.5}), Sign::Negative);
  EXPECT_EQ(squares.local_status(m, {0.6, 0.3, 0.5}), Sign::Negative);
  EXPECT_EQ(squares.local_status(m, {0.6, 0.3, -0.5}), Sign::Positive);
  EXPECT_EQ(squares.local_status(m, {0.6, 0.3, 0}), Sign::Zero);
}

}  // namespace
}  // namespace pqmesh::tet3d
