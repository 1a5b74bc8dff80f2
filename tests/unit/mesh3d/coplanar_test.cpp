// Inputs whose facets are not maximal (docs/algorithm/input.md "Merging
// coplanar facets"): a straight edge of P with a vertex in its middle
// (data/3d/cube.obj), a cap given as coplanar pieces with one marker (merged by
// make_domain, plc/merge_coplanar.hpp); flat edges between different markers
// are tested in flat_edge_test.cpp. Every mesh is checked whole (check_mesh)
// and its boundary markers are checked against the facet planes
// (mesh_check_util.hpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "../plc/domain_fixtures.hpp"
#include "mesh_check_util.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

// Meshes, checks, and checks every boundary triangle's marker: some facet
// with that marker has a plane through the ulp boxes of its three vertices.
TetMeshResult mesh_and_check(const std::string& what, const Domain3& d) {
  const TetMeshResult r = tet_mesh(d);
  test::expect_valid_with_markers(what, r, d);
  std::printf("%-28s %zu tets, %zu vertices\n", what.c_str(), r.mesh.tetrahedra.size(), r.mesh.vertices.size());
  return r;
}

bool has_vertex(const TetMesh3& m, Vec3 p) {
  for (const Vec3& q : m.vertices)
    if (q.x == p.x && q.y == p.y && q.z == p.z) return true;
  return false;
}

TEST(Coplanar, CubeObjKeepsTheVerticesInItsStraightEdges) {
  // (1, 0, 2) splits the edge between the top and front facets, (2, 1, 2)
  // the one between top and right: two facets sharing two collinear edges.
  const Domain3 d = make_domain(read_plc(test::data_path("3d/cube.obj")));
  ASSERT_EQ(d.plc.facets.size(), 6u);
  const TetMeshResult r = mesh_and_check("cube.obj", d);
  EXPECT_TRUE(has_vertex(r.mesh, {1, 0, 2}));
  EXPECT_TRUE(has_vertex(r.mesh, {2, 1, 2}));
}

TEST(Coplanar, CapsInPiecesMeshLikeTheWholeCaps) {
  // make_domain merges each cap's four trapezoids into the annulus of
  // block_with_through_hole(), with the facets in the same order and the
  // same loops (merge_coplanar_test.cpp): the same domain, so the
  // (deterministic) mesher must give the same mesh.
  const Domain3 pieces = make_domain(test::block_with_through_hole_in_pieces({1, 1, 1, 1}, {2, 2, 2, 2}, 3));
  ASSERT_EQ(pieces.plc.facets.size(), 10u);
  const TetMeshResult a = mesh_and_check("caps in pieces", pieces);
  Plc3 whole_plc = test::block_with_through_hole();
  whole_plc.facets[0].marker = 1;
  whole_plc.facets[1].marker = 2;
  for (std::size_t f = 2; f < whole_plc.facets.size(); ++f) whole_plc.facets[f].marker = 3;
  const TetMeshResult b = tet_mesh(make_domain(whole_plc));
  EXPECT_EQ(a.mesh.tetrahedra.size(), b.mesh.tetrahedra.size());
  EXPECT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
}

}  // namespace
}  // namespace pqmesh
