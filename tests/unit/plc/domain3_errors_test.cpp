// make_domain(Plc3) on deliberately broken inputs: each error code with the
// offending ids (file numbering) asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "domain_fixtures.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh {
namespace {

using test::add_box;
using test::box;

DomainError expect_error(const Plc3& plc, ErrorCode code) {
  try {
    make_domain(plc);
  } catch (const DomainError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    return e;
  }
  ADD_FAILURE() << "no DomainError, expected " << to_string(code);
  return DomainError(code, "none");
}

std::vector<std::int64_t> sorted(std::vector<std::int64_t> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(Domain3Errors, Empty) { expect_error(Plc3{}, ErrorCode::EmptyDomain); }

TEST(Domain3Errors, NonFinite) {
  Plc3 plc = box();
  plc.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  const auto e = expect_error(plc, ErrorCode::NonFinite);
  EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{3}));
}

TEST(Domain3Errors, IndexOutOfRange) {
  Plc3 plc = box();
  plc.facets[4].loops[0][2] = 99;
  const auto e = expect_error(plc, ErrorCode::IndexOutOfRange);
  EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{4}));
}

TEST(Domain3Errors, DuplicateVertexUsesFileNumberingAndLine) {
  Plc3 plc = box();
  plc.vertices.push_back(plc.vertices[0]);  // vertex 8 == vertex 0
  plc.facets[0].loops[0][0] = 8;            // ... and used by the bottom facet
  plc.source.path = "cube.poly";
  plc.source.first_id = 1;
  for (int v = 0; v < 9; ++v) plc.source.vertex_line.push_back(10 + v);
  const auto e = expect_error(plc, ErrorCode::DuplicateVertex);
  EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{1, 9}));  // indices 0 and 8, 1-based file ids
  EXPECT_EQ(e.line(), 10);
  EXPECT_EQ(e.file(), "cube.poly");
  EXPECT_NE(std::string(e.what()).find("cube.poly:10"), std::string::npos) << e.what();
}

TEST(Domain3Errors, DegenerateLoops) {
  {
    Plc3 plc = box();
    plc.facets[2].loops[0] = {0, 1};  // fewer than 3 vertices
    EXPECT_EQ(expect_error(plc, ErrorCode::DegenerateFacet).ids(), (std::vector<std::int64_t>{2}));
  }
  {
    Plc3 plc = box();
    plc.facets[3].loops[0] = {2, 6, 6, 7, 3};  // repeated consecutive vertex
    EXPECT_EQ(expect_error(plc, ErrorCode::DegenerateFacet).ids(), (std::vector<std::int64_t>{3}));
  }
  {
    Plc3 plc = box();
    plc.vertices.push_back({0.5, 0, 0});
    plc.facets.push_back(Facet3{{{0, 8, 1}}, 0});  // three collinear vertices
    EXPECT_EQ(expect_error(plc, ErrorCode::DegenerateFacet).ids(), (std::vector<std::int64_t>{6}));
  }
}

TEST(Domain3Errors, NonPlanar) {
  Plc3 plc = box();
  // (1,1,1) lifted to z = 1.5: the back (y = 1) and right (x = 1) facets stay
  // planar, the top facet bends; then also move (1,1,0) off x = 1 so the
  // right facet bends too (bottom z = 0 and back y = 1 stay planar).
  plc.vertices[7].z = 1.5;
  plc.vertices[3].x = 1.25;
  const auto e = expect_error(plc, ErrorCode::NonPlanarFacet);
  EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{1, 5}));
  EXPECT_NE(std::string(e.what()).find("facet 1 is not planar"), std::string::npos) << e.what();
}

TEST(Domain3Errors, NonPlanarByOneUlp) {
  Plc3 plc = box();
  plc.vertices[7].z = std::nextafter(1.0, 2.0);  // only the top facet (z = 1) bends
  EXPECT_EQ(expect_error(plc, ErrorCode::NonPlanarFacet).ids(), (std::vector<std::int64_t>{1}));
}

TEST(Domain3Errors, BowtieFacet) {
  Plc3 plc = box();
  plc.facets[1].loops[0] = {4, 5, 6, 7};  // (0,0,1) (1,0,1) (0,1,1) (1,1,1): sides 5-6 and 7-4 cross
  EXPECT_EQ(expect_error(plc, ErrorCode::SelfIntersectingFacet).ids(), (std::vector<std::int64_t>{1}));
}

TEST(Domain3Errors, HoleOutsideOuterLoop) {
  Plc3 plc = box({0, 0, 0}, {4, 4, 4});
  for (Vec2 p : {Vec2{5, 1}, Vec2{6, 1}, Vec2{6, 2}}) plc.vertices.push_back({p.x, p.y, 4});
  plc.facets[1].loops.push_back({8, 10, 9});
  EXPECT_EQ(expect_error(plc, ErrorCode::SelfIntersectingFacet).ids(), (std::vector<std::int64_t>{1}));
}

TEST(Domain3Errors, HoleTouchingOuterLoop) {
  Plc3 plc = box({0, 0, 0}, {4, 4, 4});
  for (Vec2 p : {Vec2{2, 0}, Vec2{3, 1}, Vec2{1, 1}}) plc.vertices.push_back({p.x, p.y, 4});  // (2,0,4) on the outer side
  plc.facets[1].loops.push_back({8, 10, 9});
  EXPECT_EQ(expect_error(plc, ErrorCode::SelfIntersectingFacet).ids(), (std::vector<std::int64_t>{1}));
}

TEST(Domain3Errors, OpenBoundary) {
  Plc3 plc = box();
  plc.facets.erase(plc.facets.begin() + 1);  // no top
  const auto e = expect_error(plc, ErrorCode::OpenBoundary);
  // The four walls (now facets 1..4) each have an open top edge.
  EXPECT_EQ(sorted(e.ids()), (std::vector<std::int64_t>{1, 2, 3, 4}));
}

TEST(Domain3Errors, NonManifoldEdge) {
  // Two boxes sharing the vertical edge x = y = 1 (their vertices merged).
  Plc3 plc = box();
  add_box(plc, {1, 1, 0}, {2, 2, 1});
  // Second box vertex 8 + 0 = (1,1,0) == vertex 3, 8 + 4 = (1,1,1) == vertex 7.
  for (auto& f : plc.facets)
    for (auto& l : f.loops)
      for (int& v : l) v = v == 8 ? 3 : (v == 12 ? 7 : v);
  const auto e = expect_error(plc, ErrorCode::NonManifoldEdge);
  // Edge (3, 7) lies on back (3), right (5) of box 1 and front (8), left (10) of box 2.
  EXPECT_EQ(sorted(e.ids()), (std::vector<std::int64_t>{3, 5, 8, 10}));
}

TEST(Domain3Errors, PinchedVertex) {
  // Two boxes sharing only the corner (1,1,1).
  Plc3 plc = box();
  add_box(plc, {1, 1, 1}, {2, 2, 2});
  for (auto& f : plc.facets)
    for (auto& l : f.loops)
      for (int& v : l) v = v == 8 ? 7 : v;
  EXPECT_EQ(expect_error(plc, ErrorCode::PinchedVertex).ids(), (std::vector<std::int64_t>{7}));
}

TEST(Domain3Errors, OverlappingBoxes) {
  Plc3 plc = box();
  add_box(plc, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  const auto e = expect_error(plc, ErrorCode::IntersectingFacets);
  ASSERT_GE(e.ids().size(), 2u);
  // The first pair named: a facet of each box (ids 0-5 and 6-11).
  EXPECT_LT(e.ids()[0], 6);
  EXPECT_GE(e.ids()[1], 6);
  EXPECT_NE(std::string(e.what()).find("intersect"), std::string::npos);
}

TEST(Domain3Errors, TetrahedronTouchingFaceAtAPoint) {
  // A tetrahedron whose lowest vertex sits exactly on the cube's top face.
  Plc3 plc = box();
  const int o = 8;
  plc.vertices.insert(plc.vertices.end(), {{0.5, 0.5, 1}, {0, 0, 2}, {1, 0, 2}, {0.5, 1, 2}});
  plc.facets.push_back(Facet3{{{o, o + 2, o + 1}}, 0});
  plc.facets.push_back(Facet3{{{o, o + 3, o + 2}}, 0});
  plc.facets.push_back(Facet3{{{o, o + 1, o + 3}}, 0});
  plc.facets.push_back(Facet3{{{o + 1, o + 2, o + 3}}, 0});
  const auto e = expect_error(plc, ErrorCode::IntersectingFacets);
  // The top facet (1) meets the three tetrahedron facets through the vertex (6, 7, 8).
  EXPECT_EQ(e.ids()[0], 1);
  EXPECT_EQ(e.ids()[1], 6);
}

TEST(Domain3Errors, FlatTetrahedronCoplanarAdjacentOverlap) {
  // A tetrahedron's four triangles squashed into the plane z = 0: every pair
  // of facets shares an edge, and across the shared edge uw the facets (u,w,a)
  // and (w,u,b) overlap (a and b on the same side of uw).
  Plc3 plc;
  plc.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}};
  plc.facets = {Facet3{{{0, 1, 2}}, 0}, Facet3{{{1, 0, 3}}, 0}, Facet3{{{0, 2, 3}}, 0}, Facet3{{{1, 3, 2}}, 0}};
  const auto e = expect_error(plc, ErrorCode::IntersectingFacets);
  EXPECT_EQ(e.ids()[0], 0);
  EXPECT_EQ(e.ids()[1], 1);
}

TEST(Domain3Errors, DisjointSolids) {
  Plc3 plc = box();
  add_box(plc, {2, 0, 0}, {3, 1, 1});
  const auto e = expect_error(plc, ErrorCode::Disconnected);
  EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{0, 6}));
}

TEST(Domain3Errors, SolidInsideCavity) {
  Plc3 plc = box({0, 0, 0}, {4, 4, 4});
  add_box(plc, {1, 1, 1}, {3, 3, 3});                // cavity
  add_box(plc, {1.5, 1.5, 1.5}, {2.5, 2.5, 2.5});    // island inside the cavity
  const auto e = expect_error(plc, ErrorCode::Disconnected);
  EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{12, 6}));  // island shell, then the cavity shell
}

TEST(Domain3Errors, HolePointInside) {
  Plc3 plc = box();
  plc.holes = {{5, 5, 5}, {0.5, 0.5, 0.5}};
  const auto e = expect_error(plc, ErrorCode::Unsupported);
  EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{1}));
}

TEST(Domain3Errors, HolePointOnBoundary) {
  Plc3 plc = box();
  plc.holes = {{1, 0.5, 0.5}};
  EXPECT_EQ(expect_error(plc, ErrorCode::Unsupported).ids(), (std::vector<std::int64_t>{0}));
}

}  // namespace
}  // namespace pqmesh
