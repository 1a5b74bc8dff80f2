// Leaf kinds (leaf_kind.hpp, thesis §4.1.7) on hand-made cubes around a unit
// cube and a thin wedge, whose expected kinds follow from the geometry of the
// chosen cube alone; and the Theorem 5 report (size_ratio.hpp) against a
// brute-force search over all pairs of leaves of a small octree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "mv3d/leaf_kind.hpp"
#include "mv3d/octree_builder.hpp"
#include "mv3d/size_ratio.hpp"
#include "octree_test_util.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::mv3d {
namespace {

Plc3 prism(const std::vector<Vec2>& poly) { return octest::extrude(poly, 1.0); }

int vertex_at(const Domain3& d, Vec3 p) {
  for (std::size_t v = 0; v < d.plc.vertices.size(); ++v)
    if (d.plc.vertices[v].x == p.x && d.plc.vertices[v].y == p.y && d.plc.vertices[v].z == p.z)
      return static_cast<int>(v);
  return -1;
}

int edge_between(const Domain3& d, Vec3 p, Vec3 q) {
  const int a = vertex_at(d, p), b = vertex_at(d, q);
  for (std::size_t e = 0; e < d.edges.size(); ++e)
    if ((d.edges[e].a == a && d.edges[e].b == b) || (d.edges[e].a == b && d.edges[e].b == a))
      return static_cast<int>(e);
  return -1;
}

// The kinds of the components of P ∩ cube (one entry per component; a cube
// missing P gives {Outside}).
std::vector<LeafClass> kinds_in(const Domain3& d, const Cube& c) {
  const LeafClassifier classify(d);
  const CubeComponents cc = components(d, c);
  if (cc.components.empty()) return {classify.classify(LeafFaces{})};
  std::vector<LeafClass> out;
  for (const ComponentFaces3& f : cc.components)
    out.push_back(classify.classify(LeafFaces{true, f.vertices, f.edges, f.facets, -1}));
  return out;
}

LeafClass only_kind(const Domain3& d, const Cube& c) {
  const std::vector<LeafClass> k = kinds_in(d, c);
  EXPECT_EQ(k.size(), 1u);
  return k.empty() ? LeafClass{} : k[0];
}

const Domain3& unit_cube() {
  static const Domain3 d = make_domain(prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  return d;
}

TEST(LeafKind, CubesAroundAUnitCube) {
  const Domain3& d = unit_cube();
  // A corner cube: the vertex (0,0,0), its three edges and three facets.
  LeafClass k = only_kind(d, {{-0.25, -0.25, -0.25}, {0.25, 0.25, 0.25}});
  EXPECT_EQ(k.kind, LeafKind::VertexCone);
  EXPECT_EQ(k.apex, vertex_at(d, {0, 0, 0}));
  // Along the vertical edge x = y = 0, away from its ends.
  k = only_kind(d, {{-0.25, -0.25, 0.25}, {0.25, 0.25, 0.75}});
  EXPECT_EQ(k.kind, LeafKind::EdgeCone);
  EXPECT_EQ(k.apex, edge_between(d, {0, 0, 0}, {0, 0, 1}));
  // Across the facet x = 0 only.
  k = only_kind(d, {{-0.25, 0.25, 0.25}, {0.25, 0.5, 0.5}});
  EXPECT_EQ(k.kind, LeafKind::FacetCone);
  // The facet x = 0 lying on the cube's lower x plane (outward shift: in the cube).
  k = only_kind(d, {{0, 0.25, 0.25}, {0.5, 0.75, 0.75}});
  EXPECT_EQ(k.kind, LeafKind::FacetCone);
  // Strictly inside, and outside.
  EXPECT_EQ(only_kind(d, {{0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}}).kind, LeafKind::EmptyInside);
  EXPECT_EQ(only_kind(d, {{2, 2, 2}, {3, 3, 3}}).kind, LeafKind::Outside);
  // Touching the corner (1,1,1) from outside: the closed cube holds the vertex.
  k = only_kind(d, {{1, 1, 1}, {2, 2, 2}});
  EXPECT_EQ(k.kind, LeafKind::VertexCone);
  EXPECT_EQ(k.apex, vertex_at(d, {1, 1, 1}));
  // Violations: the whole cube (eight vertices), and a slab through it (two
  // opposite facets, which share no edge).
  EXPECT_EQ(only_kind(d, {{-1, -1, -1}, {2, 2, 2}}).kind, LeafKind::Other);
  EXPECT_EQ(only_kind(d, {{-0.25, 0.25, 0.25}, {1.25, 0.5, 0.5}}).kind, LeafKind::Other);
  // Two edges (x = y = 0 and x = 0, y = 1) without their common facet's vertex.
  EXPECT_EQ(only_kind(d, {{-0.25, -0.25, 0.25}, {0.25, 1.25, 0.75}}).kind, LeafKind::Other);
}

TEST(LeafKind, TwoFacetsOfASharpEdgeOutsideTheBox) {
  // Triangle (0,0) (1,0) (1,1/8) extruded: the edge along z through the origin
  // has a dihedral angle of atan(1/8). A cube at x in [1/2, 3/4] spanning the
  // wedge's height (y from 0 to at most 3/32) meets its two long facets only.
  const Domain3 d = make_domain(prism({{0, 0}, {1, 0}, {1, 0.125}}));
  const LeafClass k = only_kind(d, {{0.5, -0.125, 0.25}, {0.75, 0.125, 0.5}});
  EXPECT_EQ(k.kind, LeafKind::TwoFacet);
  EXPECT_EQ(k.apex, edge_between(d, {0, 0, 0}, {0, 0, 1}));
  // The same cube moved to the edge: an edge cone.
  EXPECT_EQ(only_kind(d, {{-0.125, -0.125, 0.25}, {0.125, 0.125, 0.5}}).kind, LeafKind::EdgeCone);
}

TEST(LeafKind, HandMadeFaceListsAndUnitedBoxPieces) {
  const Domain3& d = unit_cube();
  const LeafClassifier classify(d);
  const int v0 = vertex_at(d, {0, 0, 0});
  const int e = edge_between(d, {0, 0, 0}, {0, 0, 1});
  const DomainEdge& de = d.edges[static_cast<std::size_t>(e)];
  const int f0 = std::min(de.facets[0], de.facets[1]), f1 = std::max(de.facets[0], de.facets[1]);
  const std::vector<int> verts{v0}, edges{e}, one{f0}, both{f0, f1};
  // The vertex without all its superfaces is not a vertex cone (§4.1.3 (a)).
  EXPECT_EQ(classify.classify({true, verts, edges, both, -1}).kind, LeafKind::Other);
  // An edge with one of its two facets only.
  EXPECT_EQ(classify.classify({true, {}, edges, one, -1}).kind, LeafKind::Other);
  EXPECT_EQ(classify.classify({true, {}, edges, both, -1}).kind, LeafKind::EdgeCone);
  // A piece of v0's united box holding the edge and its facets but not v0 is
  // part of the vertex cone box B; one holding a facet off v0 is not.
  const LeafClass piece = classify.classify({true, {}, edges, both, v0});
  EXPECT_EQ(piece.kind, LeafKind::VertexCone);
  EXPECT_EQ(piece.apex, v0);
  int far_facet = -1;
  for (std::size_t f = 0; f < d.plc.facets.size(); ++f) {
    bool has = false;
    for (const int w : d.plc.facets[f].loops[0]) has = has || w == v0;
    if (!has) far_facet = static_cast<int>(f);
  }
  ASSERT_GE(far_facet, 0);
  const std::vector<int> far{far_facet};
  EXPECT_EQ(classify.classify({true, {}, {}, far, v0}).kind, LeafKind::Other);
  EXPECT_EQ(classify.classify({true, {}, {}, far, -1}).kind, LeafKind::FacetCone);
}

// size_ratio against brute force: every pair of leaves meeting P, face
// sharing decided from the cube coordinates alone (no neighbour query).
TEST(SizeRatio, MatchesBruteForceOnTheLBlock) {
  const Domain3 d = octest::load_corpus("l_block.poly");
  OctreeBuilder b(d);
  b.build();
  const double alpha = compute_alpha(d.plc).radians;
  const SizeRatioReport r = size_ratio(b, alpha);
  const OctTree& t = b.tree();
  std::vector<std::int32_t> live;
  for (const std::int32_t n : b.leaves_by_id())
    if (b.data(n).has_component) live.push_back(n);
  auto side = [&](std::int32_t n) {
    const int o = b.data(n).vertex_owner;
    return o < 0 ? t.side(n) : b.vertex_box(o).hi.x - b.vertex_box(o).lo.x;
  };
  double best = std::numeric_limits<double>::infinity();
  std::int64_t pairs = 0;
  for (std::size_t i = 0; i < live.size(); ++i)
    for (std::size_t j = i + 1; j < live.size(); ++j) {
      const std::int32_t n = live[i], m = live[j];
      const int on = b.data(n).vertex_owner, om = b.data(m).vertex_owner;
      if (on >= 0 && on == om) continue;
      const Cube a = b.cube(n), c = b.cube(m);
      const double alo[3] = {a.lo.x, a.lo.y, a.lo.z}, ahi[3] = {a.hi.x, a.hi.y, a.hi.z};
      const double clo[3] = {c.lo.x, c.lo.y, c.lo.z}, chi[3] = {c.hi.x, c.hi.y, c.hi.z};
      int positive = 0, touching = 0;
      for (int k = 0; k < 3; ++k) {
        if (std::min(ahi[k], chi[k]) > std::max(alo[k], clo[k])) ++positive;
        if (ahi[k] == clo[k] || chi[k] == alo[k]) ++touching;
      }
      if (positive != 2 || touching != 1) continue;
      const bool m_big = t.level(m) <= t.level(n);
      if (!(m_big ? b.balance_adjacent(m, n) : b.balance_adjacent(n, m))) continue;
      ++pairs;
      best = std::min(best, std::min(side(n), side(m)) / std::max(side(n), side(m)) / alpha);
    }
  EXPECT_EQ(r.pairs, pairs);
  EXPECT_EQ(r.min_ratio, best);
  ASSERT_GE(r.small, 0);
  EXPECT_EQ(std::min(side(r.small), side(r.big)) / std::max(side(r.small), side(r.big)) / alpha, r.min_ratio);
  EXPECT_LE(r.h_small, r.h_big);
  std::printf("l_block: %lld adjacent pairs, min h(b)/(alpha h(B)) = %.4f (leaves %d, %d), alpha = %.4f rad\n",
              static_cast<long long>(r.pairs), r.min_ratio, r.small, r.big, alpha);
}

}  // namespace
}  // namespace pqmesh::mv3d
