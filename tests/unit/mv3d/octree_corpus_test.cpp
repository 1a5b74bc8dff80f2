// OctreeBuilder (thesis §4.1) on the data/3d corpus: the build terminates and
// the octree has the properties §4.1.1-4.1.5 promise.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "octree_test_util.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh::mv3d {
namespace {

using octest::load_corpus;

class OctreeCorpus : public ::testing::TestWithParam<const char*> {};

TEST_P(OctreeCorpus, BuildsWithLemma1BalanceAndOneVertexPerLeaf) {
  const Domain3 d = load_corpus(GetParam());
  OctreeBuilder b(d);
  const auto t0 = std::chrono::steady_clock::now();
  b.build();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const OctTree& t = b.tree();
  const OctreeStats& s = b.stats();
  std::printf("%-24s leaves %lld (outside %lld) splits v/c/e/f/bal %lld/%lld/%lld/%lld/%lld dup %lld  %.2fs\n",
              GetParam(), static_cast<long long>(s.leaves), static_cast<long long>(s.outside_leaves),
              static_cast<long long>(s.splits_vertex), static_cast<long long>(s.splits_centering),
              static_cast<long long>(s.splits_edge), static_cast<long long>(s.splits_facet),
              static_cast<long long>(s.splits_balance), static_cast<long long>(s.duplicates), secs);
  EXPECT_EQ(s.leaves, t.leaf_count());

  // Every vertex lies in some leaf's component, and is centred (Lemma 1,
  // octree_test_util.hpp).
  std::vector<int> holder(d.plc.vertices.size(), 0);
  const std::vector<std::int32_t> leaves = b.leaves_by_id();
  for (const std::int32_t n : leaves) {
    const NodeData3& nd = b.data(n);
    if (nd.has_component) {
      EXPECT_LE(nd.vertices.size(), 1u) << "leaf " << n;
    }
    for (const int v : nd.vertices) ++holder[static_cast<std::size_t>(v)];
  }
  for (std::size_t v = 0; v < d.plc.vertices.size(); ++v) {
    // A vertex on a box plane lies in every closed cube sharing it (the outward
    // shift of cube_components.hpp), so it may have several holders.
    EXPECT_GE(holder[v], 1) << "vertex " << v;
  }
  octest::expect_lemma1(b, GetParam());

  // End of the vertex phase (§4.1.3), kept by later splits (a child's P ∧ ex
  // lies in its parent's): every leaf holding a vertex v is a vertex cone, the
  // faces of P ∧ ex(b) are v and its superfaces.
  int vertex_leaves = 0;
  for (const std::int32_t n : leaves) {
    const NodeData3& nd = b.data(n);
    if (!nd.has_component || nd.vertices.size() != 1) continue;
    ++vertex_leaves;
    const int v = nd.vertices[0];
    const ExtendedFaces3 ex = b.extended_faces(n);
    EXPECT_TRUE(ex.vertices.empty() || ex.vertices == std::vector<int>{v}) << "leaf " << n;
    for (const int e : ex.edges) {
      const DomainEdge& de = d.edges[static_cast<std::size_t>(e)];
      EXPECT_TRUE(de.a == v || de.b == v) << "leaf " << n << " edge " << e;
    }
    for (const int f : ex.facets) {
      bool has_v = false;
      for (const auto& loop : d.plc.facets[static_cast<std::size_t>(f)].loops)
        for (const int w : loop) has_v = has_v || w == v;
      EXPECT_TRUE(has_v) << "leaf " << n << " facet " << f;
    }
  }
  EXPECT_GE(vertex_leaves, static_cast<int>(d.plc.vertices.size()));

  // End of the edge and facet phases (§4.1.4-4.1.5, with the 2D rule for faces
  // sharing a vertex, octree_builder.hpp): outside the united vertex boxes, a
  // leaf holding one edge e (no vertex) sees in P ∧ ex(b) only e, faces sharing
  // a vertex with e and its two facets; a leaf holding only facets, other than
  // those protected next to edge boxes (§4.1.4), holds one facet f and sees
  // only facets sharing a vertex with f.
  auto shares_vertex = [&](int f, int a, int c) {
    for (const auto& loop : d.plc.facets[static_cast<std::size_t>(f)].loops)
      for (const int w : loop)
        if (w == a || w == c) return true;
    return false;
  };
  int edge_leaves = 0, facet_leaves = 0;
  for (const std::int32_t n : leaves) {
    const NodeData3& nd = b.data(n);
    if (!nd.has_component || !nd.vertices.empty() || nd.vertex_owner >= 0) continue;
    if (!nd.edges.empty()) {
      ++edge_leaves;
      ASSERT_EQ(nd.edges.size(), 1u) << "leaf " << n;
      const DomainEdge& e = d.edges[static_cast<std::size_t>(nd.edges[0])];
      const ExtendedFaces3 ex = b.extended_faces(n);
      for (const int g : ex.edges) {
        const DomainEdge& ge = d.edges[static_cast<std::size_t>(g)];
        EXPECT_TRUE(ge.a == e.a || ge.a == e.b || ge.b == e.a || ge.b == e.b) << "leaf " << n << " edge " << g;
      }
      for (const int f : ex.facets)
        EXPECT_TRUE(f == e.facets[0] || f == e.facets[1] || shares_vertex(f, e.a, e.b)) << "leaf " << n;
      for (const int f : nd.facets) EXPECT_TRUE(f == e.facets[0] || f == e.facets[1]) << "leaf " << n;
    } else if (!nd.facets.empty() && b.protected_by(n) != OctPhase::Edge) {
      ++facet_leaves;
      ASSERT_EQ(nd.facets.size(), 1u) << "leaf " << n;
      const int f = nd.facets[0];
      const auto& fv = d.plc.facets[static_cast<std::size_t>(f)].loops;
      for (const int g : b.extended_faces(n).facets) {
        bool shares = g == f;
        for (const auto& loop : fv)
          for (const int w : loop) shares = shares || shares_vertex(g, w, w);
        EXPECT_TRUE(shares) << "leaf " << n << " facet " << g;
      }
    }
  }
  std::printf("  leaves checked: %d vertex, %d edge, %d facet\n", vertex_leaves, edge_leaves, facet_leaves);

  // Duplicates (§4.1.1): the faces of every leaf that meets ∂P are those of its
  // component of P ∩ cube, recomputed here from scratch, and two leaves of one
  // cube carry distinct components.
  std::map<std::int32_t, std::set<int>> components_at_key;  // head node of the key -> component ids
  int duplicate_leaves = 0;
  for (const std::int32_t n : leaves) {
    const NodeData3& nd = b.data(n);
    if (!nd.has_component || nd.rep_triangle < 0) continue;
    const CubeComponents cc = components(d, b.cube(n));
    const int c = t.component(n);
    ASSERT_GE(c, 0);
    ASSERT_LT(static_cast<std::size_t>(c), cc.components.size()) << "leaf " << n;
    const ComponentFaces3& f = cc.components[static_cast<std::size_t>(c)];
    EXPECT_EQ(nd.vertices, f.vertices) << "leaf " << n;
    EXPECT_EQ(nd.edges, f.edges) << "leaf " << n;
    EXPECT_EQ(nd.facets, f.facets) << "leaf " << n;
    const std::int32_t head = t.find(t.key(n));
    if (head != n || t.next_same_key(n) >= 0) ++duplicate_leaves;
    EXPECT_TRUE(components_at_key[head].insert(c).second) << "two leaves of one cube carry component " << c;
  }
  std::printf("  duplicate leaves %d\n", duplicate_leaves);
  // The Schoenhardt prism's reflex diagonals make cubes meet P in several
  // components: the octree must duplicate them.
  if (std::string(GetParam()) == "schoenhardt.poly") {
    EXPECT_GT(duplicate_leaves, 0);
  }

  // Balance condition (§4.1.1) between balance-adjacent unprotected leaves
  // (octree_test_util.hpp).
  const int checked = octest::expect_balance(b, GetParam());
  std::printf("  unbalanced neighbour pairs checked for adjacency: %d\n", checked);

  // Separating splits (§4.1.7 steps 6 and 9; octree_test_util.hpp).
  const octest::SeparationCount sep = octest::expect_separation(b, GetParam());
  std::printf("  separation: %d leaves checked; adjacent pairs sharing a vertex: %d edge, %d facet\n", sep.checked,
              sep.edge_pairs_sharing, sep.facet_pairs_sharing);
}

std::string param_name(const ::testing::TestParamInfo<const char*>& param) {
  std::string s = param.param;
  for (char& c : s)
    if (c == '.') c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(Corpus, OctreeCorpus, ::testing::ValuesIn(octest::kFastCorpus), param_name);
// With candidate lists handed down the tree the larger corpus
// models build in a few CPU seconds. The separating splits of §4.1.7 steps 6
// and 9 multiply the leaves by about 10 (pqmesh octree, Release, 2026-11-30:
// cube_through_hole 92,415 leaves 2.9 CPU s, plate_holes 128,962 / 4.9 s,
// prongs_slot 1,108,810 / 28 s, wedge_1deg 513,003 / 20 s); fins, prongs_slot
// and wedge_1deg (minutes for this whole test) stay disabled: run them with
// --gtest_also_run_disabled_tests.
const char* const kLargeCorpus[] = {"cube_through_hole.poly", "plate_holes.poly"};
const char* const kDisabledCorpus[] = {"fins.poly", "prongs_slot.poly", "wedge_1deg.poly"};
INSTANTIATE_TEST_SUITE_P(LargeCorpus, OctreeCorpus, ::testing::ValuesIn(kLargeCorpus), param_name);
INSTANTIATE_TEST_SUITE_P(DISABLED_SlowCorpus, OctreeCorpus, ::testing::ValuesIn(kDisabledCorpus), param_name);

}  // namespace
}  // namespace pqmesh::mv3d
