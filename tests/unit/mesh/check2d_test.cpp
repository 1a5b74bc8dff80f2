// The 2D validity checker on hand-built triangle meshes. Every triangle below
// was checked counter-clockwise by hand (cross product of its two edge vectors
// from the first vertex, noted where not obvious); expected kinds and ids are
// derived in the comments.
#include <gtest/gtest.h>

#include "check_fixtures.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh {
namespace {

using test::polygon_domain;

Domain2 unit_square() { return polygon_domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, 1.0); }

TriMesh2 square2() {
  TriMesh2 m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};  // cross((1,0),(1,1)) = 1, cross((1,1),(0,1)) = 1
  return m;
}

TriMesh2 square4() {
  TriMesh2 m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};  // each 0.25 area, CCW around the centre
  return m;
}

std::vector<CheckKind> kinds(const CheckReport& r) { return r.kinds(); }

TEST(Check2d, UnitSquareTwoTrianglesIsValid) {
  const CheckReport r = check_mesh(square2(), unit_square());
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.elements, 2);
  EXPECT_EQ(r.boundary_faces, 4);
  EXPECT_DOUBLE_EQ(r.mesh_volume, 1.0);
  EXPECT_NE(r.to_text().find("valid: 2 triangles, 4 vertices, 4 boundary edges"), std::string::npos) << r.to_text();
}

TEST(Check2d, UnitSquareWithCentreIsValid) {
  const CheckReport r = check_mesh(square4(), unit_square());
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.boundary_faces, 4);
}

TEST(Check2d, LShapeIsValid) {
  // L: (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), area 3; fan from (0,0):
  // areas 1, 0.5, 0.5, 1 (cross products 2, 1, 1, 2).
  const Domain2 d = polygon_domain({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, 3.0);
  TriMesh2 m;
  m.vertices = d.pslg.vertices;
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
  const CheckReport r = check_mesh(m, d);
  EXPECT_TRUE(r.valid()) << r.to_text();
}

// Square [0,3]^2 with the hole [1,2]^2: outer o0..o3 = ids 0..3, hole loop
// clockwise i0 (1,1), i3 (1,2), i2 (2,2), i1 (2,1) = ids 4..7. Each of the four
// trapezoids between them split into two triangles; area 9 - 1 = 8.
TEST(Check2d, SquareWithHoleIsValid) {
  const Domain2 d = polygon_domain({{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}, 8.0);
  const int o0 = 0, o1 = 1, o2 = 2, o3 = 3, i0 = 4, i3 = 5, i2 = 6, i1 = 7;
  TriMesh2 m;
  m.vertices = d.pslg.vertices;
  // (o0,o1,i1): cross((3,0),(2,1)) = 3; (o0,i1,i0): cross((2,1),(1,1)) = 1; the
  // other trapezoids are these rotated by 90 degrees.
  m.triangles = {{o0, o1, i1}, {o0, i1, i0}, {o1, o2, i2}, {o1, i2, i1},
                 {o2, o3, i3}, {o2, i3, i2}, {o3, o0, i0}, {o3, i0, i3}};
  const CheckReport r = check_mesh(m, d);
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.boundary_faces, 8);

  // Filling the hole with two more triangles: the mesh now covers the hole;
  // the hole's sides become interior edges (domain boundary pieces that are
  // no boundary edges) and the area is 9.
  m.triangles.push_back({i0, i1, i2});
  m.triangles.push_back({i0, i2, i3});
  const CheckReport bad = check_mesh(m, d);
  EXPECT_EQ(kinds(bad), (std::vector<CheckKind>{CheckKind::BoundaryFace, CheckKind::Volume})) << bad.to_text();
  EXPECT_EQ(bad.count(CheckKind::BoundaryFace), 4);
}

TEST(Check2d, FlippedTriangle) {
  TriMesh2 m = square2();
  m.triangles[1] = {0, 3, 2};  // clockwise
  const CheckReport r = check_mesh(m, unit_square());
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::Orientation}) << r.to_text();
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{1}));
  EXPECT_NE(r.to_text().find("[orientation] triangle 1 (0 3 2)"), std::string::npos) << r.to_text();
}

TEST(Check2d, DegenerateTriangle) {
  // Centre moved to (0.5, 0) on the bottom side: triangle 0 = (0,0) (1,0)
  // (0.5,0) is flat; the other three stay CCW (cross products 0.5, 1, 0.5).
  TriMesh2 m = square4();
  m.vertices[4] = {0.5, 0};
  const CheckReport r = check_mesh(m, unit_square());
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::DegenerateElement}) << r.to_text();
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{0}));
}

TEST(Check2d, HangingVertex) {
  // Triangle 0 = (0,0) (1,0) (1,1) has the diagonal (1,1) -> (0,0) as an edge;
  // on the other side the diagonal is split at m = (0.5, 0.5) (id 4) by
  // triangles (0, m, 3) and (m, 2, 3) (cross products 0.5 and 0.5). The cover
  // is exact (areas 0.5 + 0.25 + 0.25) but m hangs on edge (2 0).
  TriMesh2 m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  m.triangles = {{0, 1, 2}, {0, 4, 3}, {4, 2, 3}};
  const CheckReport r = check_mesh(m, unit_square());
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::NonConforming}) << r.to_text();
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{4, 2, 0}));
  // Without a domain the same is found.
  EXPECT_EQ(check_mesh_topology(m).kinds(), std::vector<CheckKind>{CheckKind::NonConforming});
}

TEST(Check2d, DuplicatedTriangle) {
  // Triangle 0 listed twice (as triangle 2): edges (0 1) and (1 2) lie on two
  // triangles on the same side; edge (0 2) is on three triangles; area 1.5.
  TriMesh2 m = square2();
  m.triangles.push_back(m.triangles[0]);
  const CheckReport r = check_mesh(m, unit_square());
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::NonConforming, CheckKind::Volume})) << r.to_text();
  EXPECT_EQ(r.count(CheckKind::NonConforming), 3);
  bool three = false;
  for (const auto& i : r.issues)
    if (i.kind == CheckKind::NonConforming && i.ids == std::vector<std::int64_t>{0, 1, 2}) three = true;
  EXPECT_TRUE(three) << r.to_text();
}

TEST(Check2d, MissingTriangle) {
  // Only triangle 0 of the square: vertex 3 is on no triangle, so the domain
  // sides (2 3) and (3 0) cannot be walked along mesh edges (MissingEdge for
  // segments 2 and 3; the boundary comparison is then skipped), and the area
  // is 0.5.
  TriMesh2 m = square2();
  m.triangles.pop_back();
  const CheckReport r = check_mesh(m, unit_square());
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::UnusedVertex, CheckKind::Volume, CheckKind::MissingEdge}))
      << r.to_text();
  EXPECT_EQ(r.count(CheckKind::MissingEdge), 2);
}

TEST(Check2d, MeshBeyondTheDomain) {
  // An extra triangle (1,0) (2,0.5) (1,1) outside the square (cross((1,0.5),(0,1)) = 1):
  // boundary edges (1 4) and (2 4) are not on the domain boundary; (1 2) becomes
  // interior; vertex 4 is outside; area 1.5.
  TriMesh2 m = square2();
  m.vertices.push_back({2, 0.5});
  m.triangles.push_back({1, 4, 2});
  const CheckReport r = check_mesh(m, unit_square());
  EXPECT_EQ(kinds(r),
            (std::vector<CheckKind>{CheckKind::BoundaryFace, CheckKind::Volume, CheckKind::VertexOutside}))
      << r.to_text();
  EXPECT_EQ(r.count(CheckKind::BoundaryFace), 3);
  EXPECT_EQ(r.count(CheckKind::VertexOutside), 1);
}

TEST(Check2d, MissingInputVertex) {
  // The domain's bottom side has a vertex at (0.5, 0) (input id 1); the mesh
  // does not.
  const Domain2 d = polygon_domain({{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, 1.0);
  TriMesh2 m = square2();
  const CheckReport r = check_mesh(m, d);
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::MissingVertex}) << r.to_text();
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{1}));
}

TEST(Check2d, InputSegmentNotRecovered) {
  // A square domain with an extra segment 4 along the diagonal (0 2); the mesh
  // splits the square along the other diagonal (1 3), so the walk from vertex
  // 0 towards 2 finds no mesh edge along the segment. (make_domain would not
  // accept an interior segment; the struct is filled directly.)
  Domain2 d = unit_square();
  d.pslg.segments.push_back({0, 2});
  TriMesh2 m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 3}, {1, 2, 3}};  // cross((1,0),(0,1)) = 1, cross((0,1),(-1,1)) = 1
  const CheckReport r = check_mesh(m, d);
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::MissingEdge}) << r.to_text();
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{4}));
  // Split along (0 2) instead, the segment is recovered.
  EXPECT_TRUE(check_mesh(square2(), d).valid());
}

TEST(Check2d, VertexOutside) {
  // An unused vertex at (5, 5), outside the unit square.
  TriMesh2 m = square2();
  m.vertices.push_back({5, 5});
  const CheckReport r = check_mesh(m, unit_square());
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::UnusedVertex, CheckKind::VertexOutside})) << r.to_text();
  for (const auto& i : r.issues) EXPECT_EQ(i.ids, (std::vector<std::int64_t>{4}));
}

TEST(Check2d, SteinerPointOnBoundaryOnlyWhenAsked) {
  // Bottom side split at m = (0.5, 0) (id 4): triangles (0 m 3), (m 1 2),
  // (m 2 3) with cross products 0.5, 0.5, 1 (areas 0.25 + 0.25 + 0.5 = 1).
  TriMesh2 m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}};
  m.triangles = {{0, 4, 3}, {4, 1, 2}, {4, 2, 3}};
  EXPECT_TRUE(check_mesh(m, unit_square()).valid());
  CheckOptions o;
  o.no_boundary_steiner = true;
  const CheckReport r = check_mesh(m, unit_square(), o);
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::SteinerOnBoundary}) << r.to_text();
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{4}));
  // An interior Steiner point is fine for the no-boundary-Steiner check.
  EXPECT_TRUE(check_mesh(square4(), unit_square(), o).valid());
}

TEST(Check2d, BadIndexStopsEarly) {
  TriMesh2 m = square2();
  m.triangles[1] = {0, 2, 7};
  const CheckReport r = check_mesh(m, unit_square());
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::BadIndex}) << r.to_text();
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{1}));
  EXPECT_FALSE(r.notes.empty());
}

TEST(Check2d, ListedEdges) {
  TriMesh2 m = square2();
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  EXPECT_TRUE(check_mesh(m, unit_square()).valid());
  m.edges.pop_back();  // boundary edge (0 3) missing from the list
  m.edges.push_back({1, 3});  // not an edge of the mesh (listed index 3)
  const CheckReport r = check_mesh(m, unit_square());
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::BoundaryFace}) << r.to_text();
  ASSERT_EQ(r.issues.size(), 2u);
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{0, 3}));
  EXPECT_EQ(r.issues[1].ids, (std::vector<std::int64_t>{3}));
}

TEST(Check2d, DuplicateVertexCoordinates) {
  // Vertex 4 repeats (1,1); triangle 1 uses it instead of 2, so the diagonal
  // is split into two unmatched edges between coincident points.
  TriMesh2 m = square2();
  m.vertices.push_back({1, 1});
  m.triangles[1] = {0, 4, 3};
  const CheckReport r = check_mesh(m, unit_square());
  EXPECT_EQ(r.kinds().front(), CheckKind::NonConforming) << r.to_text();
  bool dup = false;
  for (const auto& i : r.issues)
    if (i.ids == std::vector<std::int64_t>{2, 4}) dup = true;
  EXPECT_TRUE(dup) << r.to_text();
}

TEST(Check2d, SignedZerosAreOneCoordinate) {
  // -0 and +0 are the same coordinate: the mesh's (-0, -0) and (1, -0) are
  // the domain's (0, 0) and (1, 0) (input vertices are found by exact
  // coordinates, also without a coordinate sort), and an added vertex
  // (-0, 0) coincides with vertex 0.
  TriMesh2 m = square2();
  m.vertices[0] = {-0.0, -0.0};
  m.vertices[1] = {1, -0.0};
  EXPECT_TRUE(check_mesh(m, unit_square()).valid()) << check_mesh(m, unit_square()).to_text();
  m.vertices.push_back({-0.0, 0.0});
  m.triangles.push_back({4, 1, 2});  // (4, 1, 2) repeats triangle 0 through the copy of vertex 0
  const CheckReport r = check_mesh(m, unit_square());
  bool dup = false;
  for (const auto& i : r.issues)
    if (i.kind == CheckKind::NonConforming && i.ids == std::vector<std::int64_t>{0, 4}) dup = true;
  EXPECT_TRUE(dup) << r.to_text();
}

TEST(Check2d, ManyVerticesNoneCoincide) {
  // A 60 x 60 grid of squares, two triangles each: every vertex distinct, so
  // the checker's hash table (not the coordinate sort) decides; the mesh is
  // valid and every corner of the domain is found.
  constexpr int n = 60;
  TriMesh2 m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) m.vertices.push_back({j / double(n), i / double(n)});
  auto id = [](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      m.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  const CheckReport r = check_mesh(m, unit_square());
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.boundary_faces, 4 * n);
  m.vertices[static_cast<std::size_t>(id(n, n))] = {1, 1 - 1.0 / (4 * n)};  // moves the corner (1, 1) off it
  EXPECT_EQ(check_mesh(m, unit_square()).count(CheckKind::MissingVertex), 1);
}

TEST(Check2d, InconsistentDomainThrows) {
  Domain2 d = unit_square();
  d.pslg.segments.pop_back();  // the loop side (3 0) is no longer a segment
  EXPECT_THROW(check_mesh(square2(), d), DomainError);
}

TEST(Check2d, IssueCapCountsEverything) {
  // 10 clockwise triangles, cap 3: 3 stored, 10 counted.
  TriMesh2 m;
  for (int i = 0; i < 10; ++i) {
    const int b = static_cast<int>(m.vertices.size());
    m.vertices.push_back({double(i), 0});
    m.vertices.push_back({double(i), 1});
    m.vertices.push_back({double(i) + 1, 0});
    m.triangles.push_back({b, b + 1, b + 2});  // cross((0,1),(1,0)) = -1
  }
  CheckOptions o;
  o.max_issues_per_kind = 3;
  const CheckReport r = check_mesh_topology(m, o);
  EXPECT_EQ(r.count(CheckKind::Orientation), 10);
  EXPECT_EQ(r.issues.size(), 3u);
  EXPECT_NE(r.to_text().find("and 7 more not listed"), std::string::npos) << r.to_text();
}

}  // namespace
}  // namespace pqmesh

namespace pqmesh {
namespace {

TEST(Check2d, AgainstMakeDomain) {
  // The square given clockwise with a clockwise-given hole: make_domain orients.
  Pslg2 p;
  p.vertices = {{0, 0}, {0, 3}, {3, 3}, {3, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  p.holes = {{1.5, 1.5}};
  const Domain2 d = make_domain(p);
  // The annulus of SquareWithHoleIsValid in these ids: o0..o3 = 0 3 2 1, i0..i3 = 4 5 6 7.
  TriMesh2 m;
  m.vertices = p.vertices;
  m.triangles = {{0, 3, 5}, {0, 5, 4}, {3, 2, 6}, {3, 6, 5}, {2, 1, 7}, {2, 7, 6}, {1, 0, 4}, {1, 4, 7}};
  const CheckReport r = check_mesh(m, d);
  EXPECT_TRUE(r.valid()) << r.to_text();
  m.vertices.push_back({1.5, 1.5});  // in the hole
  EXPECT_EQ(check_mesh(m, d).kinds(), (std::vector<CheckKind>{CheckKind::UnusedVertex, CheckKind::VertexOutside}));
}

}  // namespace
}  // namespace pqmesh
