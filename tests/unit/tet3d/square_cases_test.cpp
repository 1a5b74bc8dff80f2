// The square dispatcher (square_cases.hpp) on hand-made squares: the exact
// face incidences it acts on, the cases it delegates to, and the refusals
// (InternalError naming the square and the faces met). Whole meshes of every
// box kind, and the agreement of both sides of every shared square, are in
// all_boxes_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/plc.hpp"
#include "tet3d/square_cases.hpp"
#include "tet3d/square_meets.hpp"

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
