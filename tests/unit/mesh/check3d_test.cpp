// The 3D validity checker on hand-built tetrahedral meshes. Corner ids of a
// box are i + 2j + 4k (check_fixtures.hpp). Orientations of the hand-written
// tetrahedra were derived by hand (determinants noted); expected kinds and ids
// are derived in the comments.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "check_fixtures.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace {

using test::box_corner;
using test::box_domain;
using test::box_loops;
using test::facet_domain;
using test::kuhn_grid;
using test::positive;

const Vec3 kO{0, 0, 0}, kOne{1, 1, 1};

// The unit cube in 5 tetrahedra: the central one on the odd corners 1, 2, 4, 7
// (det 2, volume 1/3) and one per even corner: (0 1 2 4) det 1; (3 2 1 7) det 1
// (from (3 1 2 7) with det -1, swapped); (5 1 4 7) det 1; (6 4 2 7) det 1.
TetMesh3 cube5() {
  TetMesh3 m;
  for (int v = 0; v < 8; ++v) m.vertices.push_back(box_corner(kO, kOne, v));
  m.tetrahedra = {{0, 1, 2, 4}, {1, 2, 4, 7}, {3, 2, 1, 7}, {5, 1, 4, 7}, {6, 4, 2, 7}};
  return m;
}

// The 12 outward boundary triangles of cube5: faces (a d c), (a b d), (a c b)
// of each corner tetrahedron (a b c d); the fourth face (b c d) is the one it
// shares with the central tetrahedron.
std::vector<std::array<int, 3>> cube5_faces() {
  return {{0, 4, 2}, {0, 1, 4}, {0, 2, 1}, {3, 7, 1}, {3, 2, 7}, {3, 1, 2},
          {5, 7, 4}, {5, 1, 7}, {5, 4, 1}, {6, 7, 2}, {6, 4, 7}, {6, 2, 4}};
}

TetMesh3 cube6() { return kuhn_grid(1, kO, 1.0); }

// [0,3]^3 without the cavity [1,2]^3: the 26 outer cells of a 3x3x3 Kuhn grid.
TetMesh3 cavity_mesh() {
  return kuhn_grid(3, kO, 1.0, [](int i, int j, int k) { return i == 1 && j == 1 && k == 1; });
}

Domain3 cavity_domain() {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.push_back(box_corner({0, 0, 0}, {3, 3, 3}, i));
  for (int i = 0; i < 8; ++i) v.push_back(box_corner({1, 1, 1}, {2, 2, 2}, i));
  auto loops = box_loops(0);
  for (auto& l : box_loops(8, /*inward=*/true)) loops.push_back(l);  // outward of P = into the cavity
  return facet_domain(v, loops, 27.0 - 1.0, /*floater_from=*/6);
}

std::vector<CheckKind> kinds(const CheckReport& r) { return r.kinds(); }

TEST(Check3d, CubeInFiveTetrahedraIsValid) {
  const TetMesh3 m = cube5();
  for (const auto& t : m.tetrahedra) ASSERT_GT(test::det6(m.vertices, t), 0);
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.boundary_faces, 12);
  EXPECT_DOUBLE_EQ(r.mesh_volume, 1.0);
  EXPECT_NE(r.to_text().find("valid: 5 tetrahedra, 8 vertices, 12 boundary triangles"), std::string::npos)
      << r.to_text();
}

TEST(Check3d, CubeInSixTetrahedraIsValid) {
  const TetMesh3 m = cube6();
  for (const auto& t : m.tetrahedra) ASSERT_GT(test::det6(m.vertices, t), 0);
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.boundary_faces, 12);
}

TEST(Check3d, CubeWithCavityIsValid) {
  const CheckReport r = check_mesh(cavity_mesh(), cavity_domain());
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.elements, 26 * 6);
  // 6 outer faces x 9 squares x 2 triangles + 6 cavity faces x 2 triangles.
  EXPECT_EQ(r.boundary_faces, 108 + 12);
  EXPECT_NEAR(r.mesh_volume, 26.0, 1e-12);  // a sum of 156 rounded volumes
}

// A square frame [0,3]^2 x [0,1] around the hole [1,2]^2 (a solid torus):
// bottom and top facets have a hole loop. Vertex ids: outer corners o0..o3 =
// (0,0) (3,0) (3,3) (0,3), hole corners i0..i3 = (1,1) (2,1) (2,2) (1,2), ids
// 0..7 at z = 0 and 8..15 at z = 1. Facets: 0 bottom, 1 top, 2..5 outer sides,
// 6..9 hole sides; every loop's normal was checked by a cross product.
Domain3 frame_domain() {
  const Vec2 ring[8] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
  std::vector<Vec3> v;
  for (int z = 0; z < 2; ++z)
    for (const Vec2& p : ring) v.push_back({p.x, p.y, double(z)});
  // Single-loop facets through the fixture, then the two facets with holes.
  const std::vector<std::vector<int>> sides = {{0, 1, 9, 8},  {1, 2, 10, 9},  {2, 3, 11, 10},  {3, 0, 8, 11},
                                               {5, 4, 12, 13}, {6, 5, 13, 14}, {7, 6, 14, 15}, {4, 7, 15, 12}};
  Domain3 d = facet_domain(v, sides, 8.0);
  // The 2D annulus triangulation (check2d_test.cpp), counter-clockwise from above.
  const int annulus[8][3] = {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  Facet3 bottom, top;
  bottom.loops = {{0, 3, 2, 1}, {4, 5, 6, 7}};      // normal -z; hole turns the other way
  top.loops = {{8, 9, 10, 11}, {12, 15, 14, 13}};   // normal +z
  d.plc.facets.insert(d.plc.facets.begin(), {bottom, top});
  for (int& owner : d.facet_triangle_owner) owner += 2;
  for (const auto& t : annulus) {
    d.facet_triangles.push_back({t[0], t[2], t[1]});
    d.facet_triangle_owner.push_back(0);
    d.facet_triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    d.facet_triangle_owner.push_back(1);
  }
  d.facet_normals.insert(d.facet_normals.begin(), {Vec3{0, 0, -1}, Vec3{0, 0, 1}});
  for (auto& e : d.edges)
    for (int& f : e.facets) f += 2;
  auto add_edge = [&](int a, int b, int f) {
    DomainEdge e;
    e.a = std::min(a, b);
    e.b = std::max(a, b);
    auto it = std::find_if(d.edges.begin(), d.edges.end(), [&](const DomainEdge& x) { return x.a == e.a && x.b == e.b; });
    it->facets[1] = f;  // every top/bottom side is also a side facet's edge
  };
  for (int f = 0; f < 2; ++f)
    for (const auto& loop : d.plc.facets[f].loops)
      for (std::size_t k = 0; k < loop.size(); ++k) add_edge(loop[k], loop[(k + 1) % loop.size()], f);
  d.shells[0].facets = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  return d;
}

TEST(Check3d, FrameWithHoledFacetsIsValid) {
  const Domain3 d = frame_domain();
  const TetMesh3 m = kuhn_grid(3, 3, 1, kO, 1.0, [](int i, int j, int) { return i == 1 && j == 1; });
  const CheckReport r = check_mesh(m, d);
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_NEAR(r.mesh_volume, 8.0, 1e-12);

  // The hole filled: the hole's vertical edges (4 12) (5 13) (6 14) (7 15) run
  // through the inside of the mesh (MissingEdge; the hole sides, which contain
  // them, are then not compared), bottom and top get two extra triangles each
  // over the hole (MissingFacet 0 and 1), and the volume is 9.
  const TetMesh3 full = kuhn_grid(3, 3, 1, kO, 1.0, [](int, int, int) { return false; });
  const CheckReport bad = check_mesh(full, d);
  EXPECT_EQ(kinds(bad), (std::vector<CheckKind>{CheckKind::Volume, CheckKind::MissingEdge, CheckKind::MissingFacet}))
      << bad.to_text();
  EXPECT_EQ(bad.count(CheckKind::MissingEdge), 4);
  ASSERT_EQ(bad.count(CheckKind::MissingFacet), 2);
  std::vector<std::int64_t> facets;
  for (const auto& i : bad.issues)
    if (i.kind == CheckKind::MissingFacet) facets.push_back(i.ids[0]);
  EXPECT_EQ(facets, (std::vector<std::int64_t>{0, 1}));
}

TEST(Check3d, ListedBoundaryFaces) {
  TetMesh3 m = cube5();
  m.faces = cube5_faces();
  EXPECT_TRUE(check_mesh(m, box_domain(kO, kOne)).valid());

  TetMesh3 reversed = m;
  std::swap(reversed.faces[0][1], reversed.faces[0][2]);  // (0 2 4): inward
  const CheckReport r = check_mesh(reversed, box_domain(kO, kOne));
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::BoundaryFace}) << r.to_text();
  // Listed index 0 names the boundary face (0 4 2) with the inward orientation.
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{0}));
  EXPECT_NE(r.issues[0].message.find("inward"), std::string::npos);

  TetMesh3 missing = m;
  missing.faces.pop_back();  // (6 2 4) not listed
  const CheckReport r2 = check_mesh(missing, box_domain(kO, kOne));
  ASSERT_EQ(kinds(r2), std::vector<CheckKind>{CheckKind::BoundaryFace}) << r2.to_text();
  EXPECT_EQ(r2.issues[0].ids, (std::vector<std::int64_t>{2, 4, 6}));
}

TEST(Check3d, FlippedTetrahedron) {
  TetMesh3 m = cube5();
  m.tetrahedra[0] = {0, 2, 1, 4};  // det -1
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::Orientation}) << r.to_text();
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{0}));
}

TEST(Check3d, DegenerateTetrahedron) {
  TetMesh3 m = cube5();
  m.tetrahedra.push_back({0, 1, 3, 2});  // all on z = 0
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::DegenerateElement}) << r.to_text();
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{5}));
}

// Box [0,1]^2 x [0,2]: the lower unit cube is cube5 (its top face split along
// the diagonal 4-7), the upper cube is the cone from m = (0.5, 0.5, 1) (id 12,
// the midpoint of 4-7) over its five faces other than the bottom, each split
// into two triangles. The volumes add up to 2 but m hangs on the lower cube's
// top triangles.
TEST(Check3d, HangingVertex) {
  TetMesh3 m = cube5();
  for (int v = 0; v < 4; ++v) m.vertices.push_back(box_corner({0, 0, 2}, {1, 1, 2}, v));  // 8..11 at z = 2
  m.vertices.push_back({0.5, 0.5, 1});                                                    // 12
  const int tris[10][3] = {{8, 9, 11}, {8, 11, 10}, {4, 5, 9}, {4, 9, 8}, {5, 7, 11},
                           {5, 11, 9}, {7, 6, 10},  {7, 10, 11}, {6, 4, 8}, {6, 8, 10}};
  for (const auto& t : tris) m.tetrahedra.push_back(positive(m.vertices, {12, t[0], t[1], t[2]}));
  for (const auto& t : m.tetrahedra) ASSERT_GT(test::det6(m.vertices, t), 0);
  const CheckReport r = check_mesh(m, box_domain(kO, {1, 1, 2}));
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::NonConforming}) << r.to_text();
  ASSERT_EQ(r.count(CheckKind::NonConforming), 1);
  EXPECT_EQ(r.issues[0].ids[0], 12);
  EXPECT_DOUBLE_EQ(r.mesh_volume, 2.0);
  EXPECT_EQ(check_mesh_topology(m).kinds(), std::vector<CheckKind>{CheckKind::NonConforming});
}

TEST(Check3d, DuplicatedTetrahedron) {
  // The central tetrahedron twice: each of its 4 faces is on 3 tetrahedra
  // (the two copies and a corner one); volume 4/3.
  TetMesh3 m = cube5();
  m.tetrahedra.push_back(m.tetrahedra[1]);
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::NonConforming, CheckKind::Volume})) << r.to_text();
  EXPECT_EQ(r.count(CheckKind::NonConforming), 4);
  for (const auto& i : r.issues)
    if (i.kind == CheckKind::NonConforming) {
      EXPECT_EQ(i.ids.size(), 3u);
      EXPECT_NE(std::find(i.ids.begin(), i.ids.end(), 1), i.ids.end());
      EXPECT_NE(std::find(i.ids.begin(), i.ids.end(), 5), i.ids.end());
    }
}

TEST(Check3d, OverlappingTetrahedra) {
  // (0 1 2 7) (det 1) lies on the same side of face (0 1 2) as corner tet 0;
  // it also puts face (1 2 7) on three tetrahedra.
  TetMesh3 m = cube5();
  m.tetrahedra.push_back({0, 1, 2, 7});
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::NonConforming, CheckKind::Volume})) << r.to_text();
  bool pair = false;
  for (const auto& i : r.issues)
    if (i.kind == CheckKind::NonConforming && i.ids == std::vector<std::int64_t>{0, 5}) pair = true;
  EXPECT_TRUE(pair) << r.to_text();
}

TEST(Check3d, MissingTetrahedronInTheBoundaryLayer) {
  // Remove the first Kuhn tetrahedron of cell (1,1,0) (tet 24: cells (0..2,0,0)
  // and (0,1,0) come first), path (1,1,0) (2,1,0) (2,2,0) (2,2,1). Its face on
  // z = 0 leaves a hole in facet 0 (MissingFacet); its other three faces become
  // boundary triangles inside the domain (BoundaryFace); volume 26 - 1/6.
  TetMesh3 m = cavity_mesh();
  const std::array<int, 4> t = m.tetrahedra[24];
  EXPECT_EQ(m.vertices[t[0]], (Vec3{1, 1, 0}));
  EXPECT_EQ(m.vertices[t[3]], (Vec3{2, 2, 1}));
  m.tetrahedra.erase(m.tetrahedra.begin() + 24);
  const CheckReport r = check_mesh(m, cavity_domain());
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::BoundaryFace, CheckKind::Volume, CheckKind::MissingFacet}))
      << r.to_text();
  EXPECT_EQ(r.count(CheckKind::BoundaryFace), 3);
  for (const auto& i : r.issues) {
    if (i.kind == CheckKind::MissingFacet) {
      EXPECT_EQ(i.ids, (std::vector<std::int64_t>{0}));
    }
  }
  EXPECT_NEAR(r.mesh_volume, 26.0 - 1.0 / 6.0, 1e-12);
}

TEST(Check3d, MissingTetrahedronAtACubeEdge) {
  // Kuhn tet 0 of the unit cube is (0 1 3 7): the only tetrahedron on the cube
  // edge (1 3), so that input edge is lost; its faces (0 7 3) and (0 1 7) become
  // boundary triangles inside the domain. The facets through (1 3) cannot be
  // compared (their edge is missing); volume 5/6.
  TetMesh3 m = cube6();
  m.tetrahedra.erase(m.tetrahedra.begin());
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::BoundaryFace, CheckKind::Volume, CheckKind::MissingEdge}))
      << r.to_text();
  EXPECT_EQ(r.count(CheckKind::BoundaryFace), 2);
  for (const auto& i : r.issues) {
    if (i.kind == CheckKind::MissingEdge) {
      EXPECT_EQ(i.ids, (std::vector<std::int64_t>{1, 3}));
    }
  }
}

TEST(Check3d, MissingInputVertex) {
  // Input vertex 8 = (0.5, 0, 0) on the cube edge (0 1), in the loops of the
  // bottom facet and the y = 0 facet (rotated to start at 8 so the fan
  // triangles are not flat). cube5 lacks it.
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.push_back(box_corner(kO, kOne, i));
  v.push_back({0.5, 0, 0});
  auto loops = box_loops(0);
  loops[0] = {8, 0, 2, 3, 1};
  loops[2] = {8, 1, 5, 4, 0};
  const CheckReport r = check_mesh(cube5(), facet_domain(v, loops, 1.0));
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::MissingVertex}) << r.to_text();
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{8}));
}

TEST(Check3d, InputEdgeNotRecovered) {
  // The bottom facet split into two coplanar triangular facets (0 2 3) and
  // (0 3 1) (normals -z) along the input edge (0 3). cube6's bottom triangles
  // are exactly those two; cube5 splits the bottom along (1 2) instead, so the
  // edge (0 3) is missing and its bottom triangles (0 2 1), (3 1 2) lie in
  // neither facet.
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.push_back(box_corner(kO, kOne, i));
  auto loops = box_loops(0);
  loops[0] = {0, 2, 3};
  loops.push_back({0, 3, 1});
  const Domain3 d = facet_domain(v, loops, 1.0);
  EXPECT_TRUE(check_mesh(cube6(), d).valid()) << check_mesh(cube6(), d).to_text();
  const CheckReport r = check_mesh(cube5(), d);
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::BoundaryFace, CheckKind::MissingEdge})) << r.to_text();
  EXPECT_EQ(r.count(CheckKind::BoundaryFace), 2);
  for (const auto& i : r.issues) {
    if (i.kind == CheckKind::MissingEdge) {
      EXPECT_EQ(i.ids, (std::vector<std::int64_t>{0, 3}));
    }
  }
}

TEST(Check3d, VertexOutside) {
  TetMesh3 m = cube5();
  m.vertices.push_back({2, 2, 2});
  const CheckReport r = check_mesh(m, box_domain(kO, kOne));
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::UnusedVertex, CheckKind::VertexOutside})) << r.to_text();
  for (const auto& i : r.issues) EXPECT_EQ(i.ids, (std::vector<std::int64_t>{8}));
}

TEST(Check3d, SteinerPointsOnBoundaryOnlyWhenAsked) {
  // The 4x4x4 grid points on the outer surface: 64 - 8 = 56, minus the 8
  // input corners = 48 Steiner points; the cavity's surface has only its 8
  // corners, all input vertices.
  CheckOptions o;
  o.no_boundary_steiner = true;
  const CheckReport r = check_mesh(cavity_mesh(), cavity_domain(), o);
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::SteinerOnBoundary}) << r.to_text();
  EXPECT_EQ(r.count(CheckKind::SteinerOnBoundary), 48);
  EXPECT_TRUE(check_mesh(cube5(), box_domain(kO, kOne), o).valid());
}

TEST(Check3d, TopologyOnly) {
  EXPECT_TRUE(check_mesh_topology(cube5()).valid());
  // Two tetrahedra sharing only the edge (0 1): (0,0,0) (1,0,0) (0,1,0) (0,0,1)
  // (det 1) and its mirror (0,0,0) (1,0,0) (0,-1,0) (0,0,-1) (det 1). The edge
  // is on four boundary triangles.
  TetMesh3 m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {0, 0, -1}};
  m.tetrahedra = {{0, 1, 2, 3}, {0, 1, 4, 5}};
  const CheckReport r = check_mesh_topology(m);
  ASSERT_EQ(kinds(r), std::vector<CheckKind>{CheckKind::BoundaryFace}) << r.to_text();
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].ids, (std::vector<std::int64_t>{0, 1}));
  EXPECT_NE(r.to_text().find("topology only"), std::string::npos);
}

TEST(Check3d, ReportTextIsReadable) {
  TetMesh3 m = cube5();
  m.tetrahedra[2] = {3, 1, 2, 7};  // det -1
  const std::string text = check_mesh(m, box_domain(kO, kOne)).to_text();
  EXPECT_EQ(text.rfind("invalid: 5 tetrahedra", 0), 0u) << text;
  EXPECT_NE(text.find("[orientation] tetrahedron 2 (3 1 2 7) is negatively oriented"), std::string::npos) << text;
  EXPECT_NE(text.find("note: conformity and domain checks skipped"), std::string::npos) << text;
}

TEST(Check3d, StructuredCubePerformance) {
  // 32^3 cells x 6 = 196608 tetrahedra of the unit cube (dyadic coordinates).
  const int n = 32;
  const TetMesh3 m = kuhn_grid(n, kO, 1.0 / n);
  const Domain3 d = box_domain(kO, kOne);
  const auto t0 = std::chrono::steady_clock::now();
  const CheckReport r = check_mesh(m, d);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("check_mesh: %zu tetrahedra, %zu vertices in %.3f s\n", m.tetrahedra.size(), m.vertices.size(),
              seconds);
  EXPECT_TRUE(r.valid()) << r.to_text();
  EXPECT_EQ(r.boundary_faces, 6 * n * n * 2);
}

// The corner tetrahedron O A B C (O the origin, A, B, C the unit points) with
// slanted facet x + y + z = 1, from make_domain.
Domain3 corner_tetrahedron() {
  Plc3 plc;
  plc.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (std::vector<int> loop : {std::vector<int>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
    Facet3 f;
    f.loops = {loop};
    plc.facets.push_back(f);
  }
  return make_domain(plc);
}

// The corner tetrahedron with one Steiner point p on facet ABC (three
// tetrahedra O + each sub-triangle), or, on_edge, p on edge AB (tetrahedra
// O A p C and O p B C).
TetMesh3 corner_split(Vec3 p, bool on_edge) {
  TetMesh3 m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, p};
  if (on_edge)
    m.tetrahedra = {positive(m.vertices, {0, 1, 4, 3}), positive(m.vertices, {0, 4, 2, 3})};
  else
    m.tetrahedra = {positive(m.vertices, {0, 1, 2, 4}), positive(m.vertices, {0, 2, 3, 4}),
                    positive(m.vertices, {0, 3, 1, 4})};
  return m;
}

// Rounded Steiner points (docs/algorithm/quality.md "The validity checker"):
// 1/3 and 2/3 have no double; their roundings lie an ulp off the slanted facet
// and edge (3 fl(1/3) != 1) and are accepted, while a point 1e-9 off is not.
TEST(Check3d, RoundedSteinerPointsOnSlantedFacetAndEdge) {
  const Domain3 d = corner_tetrahedron();
  const double third = 1.0 / 3.0, two_thirds = 2.0 / 3.0;
  // The roundings are off the facet plane and the edge exactly (else the
  // test would not exercise the rule).
  ASSERT_NE(orient3d({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {third, third, third}), Sign::Zero);
  ASSERT_NE(orient2d({1, 0}, {0, 1}, {third, two_thirds}), Sign::Zero);
  const TetMesh3 on_facet = corner_split({third, third, third}, false);
  EXPECT_TRUE(check_mesh(on_facet, d).valid()) << check_mesh(on_facet, d).to_text();
  const TetMesh3 on_edge = corner_split({third, two_thirds, 0}, true);
  EXPECT_TRUE(check_mesh(on_edge, d).valid()) << check_mesh(on_edge, d).to_text();

  const TetMesh3 off_facet = corner_split({third + 1e-9, third, third}, false);
  EXPECT_FALSE(check_mesh(off_facet, d).valid());
  const TetMesh3 off_edge = corner_split({third + 1e-9, two_thirds, 0}, true);
  EXPECT_FALSE(check_mesh(off_edge, d).valid());
}

}  // namespace
}  // namespace pqmesh

namespace pqmesh {
namespace {

// An empty mesh: every input vertex missing, volume 0, nothing else to say.
TEST(Check3d, EmptyMesh) {
  const CheckReport r = check_mesh(TetMesh3{}, box_domain(kO, kOne));
  EXPECT_EQ(kinds(r), (std::vector<CheckKind>{CheckKind::Volume, CheckKind::MissingVertex})) << r.to_text();
  EXPECT_EQ(r.count(CheckKind::MissingVertex), 8);
}

}  // namespace
}  // namespace pqmesh

namespace pqmesh {
namespace {

// The same meshes against domains built by the real make_domain (facets given
// in arbitrary orientation; make_domain orients them outward).
TEST(Check3d, AgainstMakeDomain) {
  Plc3 plc;
  for (int v = 0; v < 8; ++v) plc.vertices.push_back(box_corner(kO, kOne, v));
  for (auto loop : box_loops(0)) {
    std::reverse(loop.begin(), loop.end());  // inward on purpose
    Facet3 f;
    f.loops = {loop};
    plc.facets.push_back(f);
  }
  const Domain3 d = make_domain(plc);
  EXPECT_TRUE(check_mesh(cube5(), d).valid()) << check_mesh(cube5(), d).to_text();
  EXPECT_TRUE(check_mesh(cube6(), d).valid()) << check_mesh(cube6(), d).to_text();
  TetMesh3 outside = cube5();
  outside.vertices.push_back({0.5, 0.5, 1.5});
  EXPECT_EQ(check_mesh(outside, d).kinds(), (std::vector<CheckKind>{CheckKind::UnusedVertex, CheckKind::VertexOutside}));
}

}  // namespace
}  // namespace pqmesh
