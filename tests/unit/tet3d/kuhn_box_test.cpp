// Kuhn faces and Kuhn boxes of empty boxes (empty_box.cpp,
// docs/algorithm/tet3d_boxes.md "Empty boxes") on bare octrees of the unit
// cube: a face between two empty boxes of one size with no split point is cut
// by its diagonal c0–c2, a box with six such faces into the six Kuhn
// tetrahedra of its main diagonal; every mesh must tile the root cube
// (check_mesh against the cube as a domain).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "pqmesh/quality.hpp"
#include "tet3d/boxes/empty_boxes.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tree/tree.hpp"

namespace pqmesh::tet3d {
namespace {

// The unit cube split into 4 x 4 x 4 boxes of level 2.
OctTree grid4() {
  OctTree t(RootCube<3>{{0, 0, 0}, 1});
  t.split(0);
  for (const std::int32_t n : t.leaves()) t.split(n);
  return t;
}

// The cell index of leaf n along axis a (its lower corner in box sides).
std::int64_t cell(const OctTree& t, std::int32_t n, int a) { return t.key(n).fine_lo(a) / t.key(n).fine_side(); }

// The leaf of level 2 at cell (i, j, k).
std::int32_t leaf_at(const OctTree& t, std::int64_t i, std::int64_t j, std::int64_t k) {
  for (const std::int32_t n : t.leaves())
    if (t.level(n) == 2 && cell(t, n, 0) == i && cell(t, n, 1) == j && cell(t, n, 2) == k) return n;
  return -1;
}

void expect_tiles_cube(const BoxMesh& m) {
  const CheckReport r = check_mesh(m.mesh, make_domain(test::box()));
  EXPECT_TRUE(r.valid()) << r.to_text();
}

TEST(KuhnBoxes, UniformGridCountedByHand) {
  const OctTree t = grid4();
  const std::vector<std::int32_t> leaves = t.leaves();
  ASSERT_EQ(leaves.size(), 64u);
  const BoxMesh m = mesh_empty_boxes(t, CornerSet(t, leaves), leaves);
  expect_tiles_cube(m);
  // Inner faces (3 axes x 3 planes x 16) are Kuhn faces, counted from both
  // sides; faces on the root cube have no box across.
  EXPECT_EQ(m.stats.kuhn_faces, 2 * 144);
  // The 2 x 2 x 2 inner boxes have six Kuhn faces: 6 tetrahedra each. A box
  // with b faces on the root cube: 4 b + 2 (6 - b) cones from its centre;
  // 24 boxes have b = 1, 24 have b = 2, 8 have b = 3.
  EXPECT_EQ(m.stats.empty_kuhn, 8);
  EXPECT_EQ(m.mesh.tetrahedra.size(), 8u * 6 + 24u * 14 + 24u * 16 + 8u * 18);
  // Vertices: 5^3 corners, 6 x 16 face centres on the root cube, the centres
  // of the 56 coned boxes (Kuhn boxes have none).
  EXPECT_EQ(m.mesh.vertices.size(), 125u + 96u + 56u);
}

TEST(KuhnBoxes, KuhnBoxIsSixTetrahedraAlongItsMainDiagonal) {
  const OctTree t = grid4();
  const std::vector<std::int32_t> leaves = t.leaves();
  const BoxMesh m = mesh_empty_boxes(t, CornerSet(t, leaves), leaves);
  const std::int32_t inner = leaf_at(t, 1, 2, 1);
  ASSERT_GE(inner, 0);
  const Vec3 lo{0.25, 0.5, 0.25}, hi{0.5, 0.75, 0.5};
  int count = 0;
  double volume = 0;
  for (std::size_t i = 0; i < m.mesh.tetrahedra.size(); ++i) {
    if (m.tet_leaf[i] != inner) continue;
    ++count;
    const auto& k = m.mesh.tetrahedra[i];
    const auto& V = m.mesh.vertices;
    bool has_lo = false, has_hi = false;
    for (const int v : k) {
      has_lo = has_lo || V[static_cast<std::size_t>(v)] == lo;
      has_hi = has_hi || V[static_cast<std::size_t>(v)] == hi;
    }
    EXPECT_TRUE(has_lo && has_hi) << "tetrahedron " << i << " misses the main diagonal";
    volume += signed_volume(V[static_cast<std::size_t>(k[0])], V[static_cast<std::size_t>(k[1])],
                            V[static_cast<std::size_t>(k[2])], V[static_cast<std::size_t>(k[3])]);
  }
  EXPECT_EQ(count, 6);
  // Six tetrahedra of volume s^3 / 6 each (s = 1/4), summed in double.
  EXPECT_NEAR(volume, 0.25 * 0.25 * 0.25, 1e-15);
}

TEST(KuhnBoxes, FacesNextToASplitBoxAreNoKuhnFaces) {
  // Split the inner box at cell (1, 1, 1): its face neighbours lose that face,
  // its edge neighbours the two faces through the split edge (a corner of
  // its children at the edge's midpoint), its children touch level-2 boxes.
  // Of the other inner boxes only (2, 2, 2), which shares a single corner
  // with it, keeps six Kuhn faces.
  OctTree t = grid4();
  t.split(leaf_at(t, 1, 1, 1));
  const std::vector<std::int32_t> leaves = t.leaves();
  const BoxMesh m = mesh_empty_boxes(t, CornerSet(t, leaves), leaves);
  expect_tiles_cube(m);
  EXPECT_EQ(m.stats.empty_kuhn, 1);
}

}  // namespace
}  // namespace pqmesh::tet3d
