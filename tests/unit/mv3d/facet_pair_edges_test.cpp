// FacetPairEdges (facet_pair_edges.hpp) against a scan of Domain3::edges over
// every facet pair of corpus models, and faces_text (leaf_kind.hpp) on the
// 1-based cube.poly, whose expected text is read off the file by hand.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "mv3d/facet_pair_edges.hpp"
#include "mv3d/leaf_kind.hpp"
#include "octree_test_util.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh::mv3d {
namespace {

// The lowest edge index on both f and g, by scanning every edge.
int scan_edge_between(const Domain3& d, int f, int g) {
  for (std::size_t e = 0; e < d.edges.size(); ++e) {
    const DomainEdge& de = d.edges[e];
    if ((de.facets[0] == f && de.facets[1] == g) || (de.facets[0] == g && de.facets[1] == f))
      return static_cast<int>(e);
  }
  return -1;
}

TEST(FacetPairEdges, AgreesWithAScanOnEveryFacetPair) {
  for (const char* name : {"cube.poly", "l_block.poly", "plate_holes.poly", "star_vertex.poly", "schoenhardt.poly"}) {
    const Domain3 d = octest::load_corpus(name);
    const FacetPairEdges lookup(d);
    const int nf = static_cast<int>(d.plc.facets.size());
    int shared = 0;
    for (int f = 0; f < nf; ++f)
      for (int g = 0; g < nf; ++g) {
        const int want = f == g ? -1 : scan_edge_between(d, f, g);
        ASSERT_EQ(lookup.edge_between(f, g), want) << name << ": facets " << f << ", " << g;
        shared += want >= 0 ? 1 : 0;
      }
    // Every edge is found from its own facets, in both orders.
    EXPECT_GE(shared, static_cast<int>(d.edges.size())) << name;
  }
}

TEST(FacetPairEdges, OppositeCubeFacetsShareNoEdge) {
  const Domain3 d = octest::load_corpus("cube.poly");
  const FacetPairEdges lookup(d);
  int none = 0;
  for (int f = 0; f < 6; ++f)
    for (int g = f + 1; g < 6; ++g) none += lookup.edge_between(f, g) < 0 ? 1 : 0;
  EXPECT_EQ(none, 3);  // 15 pairs, 12 edges
}

TEST(FacesText, NamesFacesInTheFileNumbering) {
  const Domain3 d = octest::load_corpus("cube.poly");  // 1-based ids
  int edge = -1;
  for (std::size_t e = 0; e < d.edges.size(); ++e)
    if ((d.edges[e].a == 0 && d.edges[e].b == 1) || (d.edges[e].a == 1 && d.edges[e].b == 0))
      edge = static_cast<int>(e);
  ASSERT_GE(edge, 0);
  const std::vector<int> edges{edge}, facets{2, 4}, vertices{6};
  EXPECT_EQ(faces_text(d, LeafFaces{true, {}, edges, facets, -1}), "vertices none; edges 1-2; facets 3, 5");
  EXPECT_EQ(faces_text(d, LeafFaces{true, vertices, {}, {}, -1}), "vertices 7; edges none; facets none");
}

}  // namespace
}  // namespace pqmesh::mv3d
