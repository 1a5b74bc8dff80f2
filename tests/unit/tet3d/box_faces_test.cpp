// Box facet triangulation (§4.4 Case A) and empty-box tetrahedra (§4.5.1) on
// bare octrees of the unit cube: meshing every leaf must tile the root cube,
// which check_mesh verifies against the cube as a domain. Trees are refined at
// random, balanced or not (protected boxes make unbalanced neighbours possible,
// box_faces.hpp), so the face subdivision and edge splits are exercised with
// level jumps of one and of several.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/boxes/empty_boxes.hpp"
#include "tree/tree.hpp"

namespace pqmesh::tet3d {
namespace {

OctTree unit_tree() { return OctTree(RootCube<3>{{0, 0, 0}, 1}); }

std::vector<std::int32_t> all_leaves(const OctTree& t) { return t.leaves(); }

TEST(BoxFaces, SingleCubeIsCoupledFromCentreToFaceCentres) {
  // One box, no neighbours: each face is one square with four unsplit sides,
  // so 6 x 4 triangles and tetrahedra; vertices: 8 corners, 6 face centres, 1 centre.
  const OctTree t = unit_tree();
  const std::vector<std::int32_t> leaves = all_leaves(t);
  const CornerSet corners(t, leaves);
  EXPECT_EQ(corners.size(), 8u);
  const BoxMesh m = mesh_empty_boxes(t, corners, leaves);
  EXPECT_EQ(m.mesh.tetrahedra.size(), 24u);
  EXPECT_EQ(m.mesh.vertices.size(), 15u);
  const CheckReport r = check_mesh(m.mesh, make_domain(test::box()));
  EXPECT_TRUE(r.valid()) << r.to_text();
}

TEST(BoxFaces, FaceNextToSmallerBoxesIsSplitIntoTheirSquares) {
  // Root split once, child 0 split again: the faces of children 1, 2, 4 that
  // touch child 0 are split into four squares each, and their edges on child
  // 0's side are split at the midpoints.
  OctTree t = unit_tree();
  const std::int32_t first = t.split(0);
  t.split(first);
  const std::vector<std::int32_t> leaves = all_leaves(t);
  const CornerSet corners(t, leaves);
  std::vector<GridTriangle> tris;
  // Child 1 is the box [1/2, 1] x [0, 1/2] x [0, 1/2]; its lower x face touches child 0.
  triangulate_box_face(t.key(first + 1), 0, false, corners, tris);
  // Four squares of side 1/4; the only split points on their sides are corners
  // of the level-2 boxes, which are the squares' own corners: 4 x 4 triangles.
  EXPECT_EQ(tris.size(), 16u);
  tris.clear();
  // Its upper x face lies on the root boundary: one square, no split points.
  triangulate_box_face(t.key(first + 1), 0, true, corners, tris);
  EXPECT_EQ(tris.size(), 4u);
  tris.clear();
  // Its lower y face (y = 0) is one square whose edge x = 1/2 is split at z = 1/4
  // by the corner of child 0's children: 5 triangles.
  triangulate_box_face(t.key(first + 1), 1, false, corners, tris);
  EXPECT_EQ(tris.size(), 5u);
  const BoxMesh m = mesh_empty_boxes(t, corners, leaves);
  const CheckReport r = check_mesh(m.mesh, make_domain(test::box()));
  EXPECT_TRUE(r.valid()) << r.to_text();
}

// Splits random leaves up to level `max_level`; balances when asked.
OctTree random_tree(std::uint64_t seed, int splits, int max_level, bool balanced) {
  OctTree t = unit_tree();
  std::mt19937_64 rng(seed);
  for (int i = 0; i < splits; ++i) {
    const std::vector<std::int32_t> leaves = t.leaves();
    const std::int32_t n = leaves[static_cast<std::size_t>(rng() % leaves.size())];
    if (t.level(n) < max_level) t.split(n);
  }
  if (balanced) t.balance_all();
  return t;
}

TEST(BoxFaces, RandomTreesTileTheRootCube) {
  int max_jump = 0;
  std::int64_t kuhn_boxes = 0, kuhn_faces = 0;
  for (const bool balanced : {true, false}) {
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
      const OctTree t = random_tree(seed, 40, 6, balanced);
      const std::vector<std::int32_t> leaves = all_leaves(t);
      for (const std::int32_t n : leaves)
        for (const std::int32_t m : t.neighbours(n)) max_jump = std::max(max_jump, t.level(m) - t.level(n));
      const BoxMesh m = mesh_empty_boxes(t, CornerSet(t, leaves), leaves);
      kuhn_boxes += m.stats.empty_kuhn;
      kuhn_faces += m.stats.kuhn_faces;
      const CheckReport r = check_mesh(m.mesh, make_domain(test::box()));
      ASSERT_TRUE(r.valid()) << "seed " << seed << (balanced ? " balanced\n" : " unbalanced\n") << r.to_text();
      // Vertex identity is the grid key: no two vertices share a key.
      ASSERT_EQ(std::set<VertexKey>(m.keys.begin(), m.keys.end()).size(), m.keys.size());
      for (const VertexKey& k : m.keys) ASSERT_EQ(k.kind, VertexKind::Grid);
    }
  }
  // The unbalanced trees did contain neighbours more than one level apart,
  // and the trees had Kuhn faces and Kuhn boxes (empty_box.cpp) next to them.
  EXPECT_GE(max_jump, 2);
  EXPECT_GT(kuhn_faces, 0);
  EXPECT_GT(kuhn_boxes, 0);
}

TEST(BoxFaces, OutputIsDeterministic) {
  const OctTree t = random_tree(7, 60, 6, false);
  const std::vector<std::int32_t> leaves = all_leaves(t);
  const BoxMesh a = mesh_empty_boxes(t, CornerSet(t, leaves), leaves);
  const BoxMesh b = mesh_empty_boxes(t, CornerSet(t, leaves), leaves);
  EXPECT_EQ(a.mesh.tetrahedra, b.mesh.tetrahedra);
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);
}

}  // namespace
}  // namespace pqmesh::tet3d
