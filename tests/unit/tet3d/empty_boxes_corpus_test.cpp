// Empty-box tetrahedra (§4.5.1) on the octrees of the data/3d corpus.
//
// Grid-aligned models (cube, L-block: every facet lies on a box plane of the
// octree) are the union of their "flush" leaves (empty_boxes.hpp), so meshing
// those leaves gives a mesh of P and check_mesh must pass. For the other
// models only the empty inside leaves (no P face in the closed cube) are
// meshed, and this test checks the partial mesh itself:
//   * every tetrahedron has positive orientation (exact orient3d);
//   * a triangle interior to the union of the meshed leaves (the leaf across
//     it, found by point location in the tree, is meshed too) lies on exactly
//     two tetrahedra with opposite orientations, and a triangle on the union's
//     boundary on exactly one;
//   * the total volume equals the sum of the leaf volumes.
// The quality of the tetrahedra (aspect ratio, dihedral angles) is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/read_domain.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"
#include "tet3d/boxes/empty_boxes.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/facet_plane.hpp"

namespace pqmesh::tet3d {
namespace {

// The octree without the separating splits of §4.1.7 steps 6 and 9
// (OctreeOptions::separate): ten times fewer leaves, so these box-meshing
// tests stay fast (with the splits: DISABLED_StarVertexUnwarped below).
mv3d::OctreeOptions unseparated() {
  mv3d::OctreeOptions o;
  o.separate = false;
  return o;
}

Domain3 load(const std::string& name) { return make_domain(read_plc(test::data_path("3d/" + name))); }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void print_quality(const char* name, const char* what, const TetMesh3& mesh, double secs) {
  const QualityReport q = quality_report(mesh);
  std::printf("%-18s %-6s %7lld tets, aspect max %.3f mean %.3f, dihedral %.2f..%.2f deg, %.3fs\n", name, what,
              static_cast<long long>(q.elements), q.aspect_ratio.max, q.aspect_ratio.mean, q.min_angle.min,
              q.max_angle.max, secs);
}

double leaf_volume(const mv3d::OctreeBuilder& b, std::int32_t n) {
  const double s = b.tree().side(n);
  return s * s * s;
}

class GridAligned : public ::testing::TestWithParam<const char*> {};

TEST_P(GridAligned, FlushLeavesMeshTheDomain) {
  const Domain3 d = load(GetParam());
  mv3d::OctreeBuilder b(d, unseparated());
  b.build();
  const std::vector<std::int32_t> flush = empty_leaves(b, true);
  const std::vector<std::int32_t> empty = empty_leaves(b, false);
  double empty_volume = 0;
  for (const std::int32_t n : empty) empty_volume += leaf_volume(b, n);
  std::printf("%s: %zu flush leaves, %zu of them empty inside (volume %.4f of %.4f)\n", GetParam(), flush.size(),
              empty.size(), empty_volume, d.volume);
  const auto t0 = std::chrono::steady_clock::now();
  const BoxMesh m = mesh_empty_boxes(b, flush);
  print_quality(GetParam(), "flush", m.mesh, seconds_since(t0));
  const CheckReport r = check_mesh(m.mesh, d);
  EXPECT_TRUE(r.valid()) << r.to_text();
}

INSTANTIATE_TEST_SUITE_P(Corpus, GridAligned, ::testing::Values("cube.poly", "l_block.poly"));

// The partial-mesh check of the header comment, for meshes of empty boxes
// (facet -1) and facet boxes (facet >= 0, P ∧ b = cube ∩ P's side of F):
// `facet_of[leaf]` is -2 for leaves not meshed. A triangle is on the union's
// boundary if it lies on its leaf's facet F (its vertices within an ulp of
// F's plane), or if no meshed leaf across it holds the triangle's centroid in
// its piece (for a facet box: the centroid not beyond its facet). Returns the
// number of interior triangles.
// With `locate_across` false (warped meshes: a warped vertex bends box faces,
// and the point-location rule can land on the wrong side), triangles on one
// tetrahedron that are not on F are not classified; the conformity of warped
// boxes is checked by the half-space test of facet_boxes_test.cpp instead
// (check_mesh_topology on a closed mesh).
std::int64_t check_partial(const mv3d::OctreeBuilder& b, const std::vector<int>& facet_of, const TetMesh3& mesh,
                           const std::vector<std::int32_t>& tet_leaf, bool locate_across = true) {
  const OctTree& t = b.tree();
  const Domain3& d = b.domain();
  auto plane = [&](int f) {
    for (std::size_t i = 0; i < d.facet_triangles.size(); ++i)
      if (d.facet_triangle_owner[i] == f) return d.facet_triangles[i];
    return std::array<int, 3>{-1, -1, -1};
  };
  auto side = [&](int f, Vec3 p) {
    const auto tri = plane(f);
    const auto& P = d.plc.vertices;
    return orient3d(P[static_cast<std::size_t>(tri[0])], P[static_cast<std::size_t>(tri[1])],
                    P[static_cast<std::size_t>(tri[2])], p);
  };
  auto within = [&](int f, Vec3 p) {
    const auto tri = plane(f);
    const auto& P = d.plc.vertices;
    return within_ulp_of_plane(p, P[static_cast<std::size_t>(tri[0])], P[static_cast<std::size_t>(tri[1])],
                               P[static_cast<std::size_t>(tri[2])]);
  };
  const auto& V = mesh.vertices;
  // Sorted triangle -> (tet, parity of the tet's face orientation relative to the sorted order).
  std::map<std::array<int, 3>, std::vector<std::pair<std::size_t, bool>>> faces;
  for (std::size_t i = 0; i < mesh.tetrahedra.size(); ++i) {
    const auto& k = mesh.tetrahedra[i];
    EXPECT_EQ(orient3d(V[k[0]], V[k[1]], V[k[2]], V[k[3]]), Sign::Positive) << "tet " << i;
    // Outward faces of a positive tet (a, b, c, d).
    const std::array<std::array<int, 3>, 4> out = {{{k[0], k[2], k[1]}, {k[0], k[1], k[3]}, {k[1], k[2], k[3]},
                                                     {k[0], k[3], k[2]}}};
    for (const auto& f : out) {
      std::array<int, 3> s = f;
      // Rotate so the smallest index comes first; then the orientation is the order of the other two.
      while (s[0] != std::min({f[0], f[1], f[2]})) s = {s[1], s[2], s[0]};
      const bool parity = s[1] < s[2];
      faces[{s[0], std::min(s[1], s[2]), std::max(s[1], s[2])}].push_back({i, parity});
    }
  }
  std::int64_t interior = 0;
  std::vector<std::int32_t> across;
  for (const auto& [tri, users] : faces) {
    const std::size_t first = users[0].first;
    const std::int32_t own = tet_leaf[first];
    const int own_facet = facet_of[static_cast<std::size_t>(own)];
    bool on_facet = own_facet >= 0;
    for (const int v : tri) on_facet = on_facet && within(own_facet, V[static_cast<std::size_t>(v)]);
    // Two tetrahedra of one leaf: a triangle inside the leaf (checked for
    // opposite sides below; the point-location rule would need a step
    // smaller than the triangle's distance to the box faces).
    bool inner = users.size() == 2 && tet_leaf[users[1].first] == own && !on_facet;
    EXPECT_LE(users.size(), 2u);
    if (!locate_across && !on_facet && !inner) {
      if (users.size() == 2) {
        EXPECT_NE(users[0].second, users[1].second) << "same side";
      }
      continue;
    }
    if (!on_facet && !inner) {
      // The point just across the triangle from its first tetrahedron (away
      // from that tetrahedron's fourth vertex), by a small fraction of the
      // triangle's size: a triangle on a box face lies in one square of the
      // finer side, well inside it, so the point lands in the leaf across.
      const Vec3 c = (1.0 / 3) * (V[tri[0]] + V[tri[1]] + V[tri[2]]);
      const Vec3 n = cross(V[tri[1]] - V[tri[0]], V[tri[2]] - V[tri[0]]);
      int opposite = -1;
      for (const int v : mesh.tetrahedra[first])
        if (v != tri[0] && v != tri[1] && v != tri[2]) opposite = v;
      Vec3 dir = (1.0 / norm(n)) * n;
      if (dot(dir, c - V[static_cast<std::size_t>(opposite)]) < 0) dir = -1.0 * dir;
      const Vec3 p = c + (std::sqrt(norm(n)) / 16) * dir;
      t.leaves_containing({p.x, p.y, p.z}, across);
      for (const std::int32_t a : across) {
        const int fa = facet_of[static_cast<std::size_t>(a)];
        inner = inner || fa == -1 || (fa >= 0 && side(fa, c) != Sign::Positive);
      }
    }
    if (inner) {
      ++interior;
      EXPECT_EQ(users.size(), 2u) << "interior triangle " << tri[0] << " " << tri[1] << " " << tri[2];
      if (users.size() == 2) {
        EXPECT_NE(users[0].second, users[1].second) << "same side";
      }
    } else {
      EXPECT_EQ(users.size(), 1u) << "boundary triangle " << tri[0] << " " << tri[1] << " " << tri[2]
                                  << (on_facet ? " on F" : "") << " in leaf " << own;
    }
  }
  return interior;
}

class EmptyInside : public ::testing::TestWithParam<const char*> {};

TEST_P(EmptyInside, PartialMeshIsConforming) {
  const Domain3 d = load(GetParam());
  mv3d::OctreeBuilder b(d, unseparated());
  b.build();
  const std::vector<std::int32_t> leaves = empty_leaves(b, false);
  ASSERT_FALSE(leaves.empty());
  const auto t0 = std::chrono::steady_clock::now();
  const BoxMesh m = mesh_empty_boxes(b, leaves);
  const double secs = seconds_since(t0);
  print_quality(GetParam(), "empty", m.mesh, secs);
  std::vector<int> facet_of(static_cast<std::size_t>(b.tree().size()), -2);
  for (const std::int32_t n : leaves) facet_of[static_cast<std::size_t>(n)] = -1;
  const std::int64_t interior = check_partial(b, facet_of, m.mesh, m.tet_leaf);
  EXPECT_GT(interior, 0);
  double volume = 0, expected = 0;
  const auto& V = m.mesh.vertices;
  for (const auto& k : m.mesh.tetrahedra) volume += signed_volume(V[k[0]], V[k[1]], V[k[2]], V[k[3]]);
  for (const std::int32_t n : leaves) expected += leaf_volume(b, n);
  // Summing N volumes in double: relative error up to about N eps.
  const double tets = static_cast<double>(m.mesh.tetrahedra.size());
  EXPECT_NEAR(volume, expected, 4 * tets * std::numeric_limits<double>::epsilon() * expected);
  // What the tree guarantees around empty boxes (reported, not assumed by
  // box_faces.hpp): the largest level jump to a neighbour meeting P.
  // Jumps above one are counted with the larger box protected (exempt from
  // balance, §4.1.1) or not.
  int jump = 0;
  std::int64_t big_protected = 0, big_unprotected = 0;
  for (const std::int32_t n : leaves)
    for (const std::int32_t a : b.tree().neighbours(n)) {
      if (!b.data(a).has_component) continue;
      const int j = std::abs(b.tree().level(a) - b.tree().level(n));
      jump = std::max(jump, j);
      if (j > 1) ++(b.tree().is_protected(b.tree().level(a) < b.tree().level(n) ? a : n) ? big_protected : big_unprotected);
    }
  std::printf("%-18s largest level jump from an empty box to a neighbour meeting P: %d (pairs > 1: %lld with the larger box protected, %lld not)\n",
              GetParam(), jump, static_cast<long long>(big_protected), static_cast<long long>(big_unprotected));
}

INSTANTIATE_TEST_SUITE_P(Corpus, EmptyInside,
                         ::testing::Values("cube.poly", "cube_cavity.poly", "l_block.poly", "schoenhardt.poly",
                                           "star_vertex.poly", "wedge_5deg.poly"));

// Empty boxes plus facet boxes (§4.5.4, before warping) of the octree: a
// leaf outside every united vertex box whose component holds no P vertex or
// edge and one facet F is a facet box when F's plane separates its corners,
// an empty box when no corner is beyond F (F touches the cube), and is left
// out when no corner is on P's side.
void check_facet_boxes(const char* name, bool warp, const mv3d::OctreeOptions& options) {
  const Domain3 d = load(name);
  mv3d::OctreeBuilder b(d, options);
  b.build();
  const OctTree& t = b.tree();
  std::vector<BoxJob> jobs;
  std::vector<int> facet_of(static_cast<std::size_t>(t.size()), -2);
  for (const std::int32_t n : b.leaves_by_id()) {
    const mv3d::NodeData3& nd = b.data(n);
    if (!nd.has_component || nd.vertex_owner >= 0 || !nd.vertices.empty() || !nd.edges.empty()) continue;
    int facet = -1;
    if (nd.rep_triangle != -1) {
      if (nd.facets.size() != 1) continue;
      const FacetPlane plane(d, nd.facets[0]);
      bool in = false, out = false;
      for (int k = 0; k < 8; ++k) {
        const Sign s = plane.side(grid_coordinates(t, key_corner(t.key(n), k)));
        in = in || s == Sign::Negative;
        out = out || s == Sign::Positive;
      }
      if (!in) continue;
      if (out) facet = nd.facets[0];
    }
    jobs.push_back({n, facet});
    facet_of[static_cast<std::size_t>(n)] = facet;
  }
  const auto t0 = std::chrono::steady_clock::now();
  BoxMeshOptions opt;
  opt.warp = warp;
  const BoxMesh m = mesh_boxes(t, CornerSet(b), d, jobs, opt);
  const double secs = seconds_since(t0);
  print_quality(name, warp ? "warped" : "facet", m.mesh, secs);
  std::printf("%-18s boxes: empty %lld, facet with centre inside %lld, moved onto F %lld, beyond F %lld; warped %lld (conflicts %lld)\n",
              name, static_cast<long long>(m.stats.empty), static_cast<long long>(m.stats.inside),
              static_cast<long long>(m.stats.on_facet), static_cast<long long>(m.stats.beyond),
              static_cast<long long>(m.warped), static_cast<long long>(m.warp_conflicts));
  EXPECT_GT(check_partial(b, facet_of, m.mesh, m.tet_leaf, !warp), 0);
  // Where the worst tetrahedron is: its leaf's level and facet, its vertex kinds.
  const QualityReport q = quality_report(m.mesh);
  if (q.aspect_ratio.argmax >= 0) {
    const auto w = static_cast<std::size_t>(q.aspect_ratio.argmax);
    const std::int32_t leaf = m.tet_leaf[w];
    std::printf("%-18s worst tet: leaf level %d facet %d, vertex kinds", name, t.level(leaf),
                facet_of[static_cast<std::size_t>(leaf)]);
    for (const int v : m.mesh.tetrahedra[w]) std::printf(" %d", static_cast<int>(m.keys[static_cast<std::size_t>(v)].kind));
    std::printf("\n");
  }
}

class FacetBoxCorpus : public ::testing::TestWithParam<std::tuple<const char*, bool>> {};

TEST_P(FacetBoxCorpus, PartialMeshIsConforming) {
  check_facet_boxes(std::get<0>(GetParam()), std::get<1>(GetParam()), unseparated());
}

// The octree with the separating splits (689,684 tets): the partial mesh is
// conforming because CornerSet(builder) takes the corners of every leaf
// (box_faces.cpp), so both sides of a face cut it into the same squares.
// Disabled for time (10 s).
TEST(FacetBoxCorpusSeparated, DISABLED_StarVertexUnwarped) { check_facet_boxes("star_vertex.poly", false, {}); }

INSTANTIATE_TEST_SUITE_P(Corpus, FacetBoxCorpus,
                         ::testing::Combine(::testing::Values("cube.poly", "cube_cavity.poly", "l_block.poly",
                                                              "schoenhardt.poly", "star_vertex.poly", "wedge_5deg.poly"),
                                            ::testing::Bool()));

}  // namespace
}  // namespace pqmesh::tet3d
