#pragma once
// Invariant checks of a finished OctreeBuilder (thesis §4.1-4.2), shared by
// tests/unit/mv3d/octree_corpus_test.cpp (corpus), octree_geodesic_test.cpp
// and tests/property/octree_property_test.cpp (corpus and random polyhedra).
// Each check reports failures through gtest EXPECT_* with `label` (the input's
// name) and returns what it counted, for the test's printed summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../plc/domain_fixtures.hpp"
#include "mv3d/leaf_kind.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh::mv3d::octest {

// The prism over a counter-clockwise polygon in the xy-plane, z in [0, depth]
// (vertices: the polygon at z = 0, then at z = depth; facets: bottom, top,
// then side i from polygon vertex i to i + 1, the layout of
// data/generate_corpus.py's prism()).
inline Plc3 extrude(const std::vector<Vec2>& poly, double depth) { return test::prism(poly, 0, depth); }

// The tuning fork of the geodesic tests (octree and tet mesh): the
// plate [0,1]^2 x [0,1/4] minus the square cavity [1/4,3/4]^2 and a neck of
// width w (rounded to a multiple of 2^-12, so every coordinate is dyadic)
// that opens the cavity to the outside. w = 1e-1 is data/3d/tuning_fork.poly.
inline Plc3 tuning_fork(double w) {
  w = std::round(w * 4096) / 4096;
  const double a = 0.5 - w / 2, b = 0.5 + w / 2;
  return extrude({{0, 0},
                  {1, 0},
                  {1, 1},
                  {b, 1},
                  {b, 0.75},
                  {0.75, 0.75},
                  {0.75, 0.25},
                  {0.25, 0.25},
                  {0.25, 0.75},
                  {a, 0.75},
                  {a, 1},
                  {0, 1}},
                 0.25);
}

inline Domain3 load_corpus(const std::string& name) {
  return make_domain(read_plc(pqmesh::test::data_path("3d/" + name)));
}

// The corpus files whose octree takes a few seconds at most (Release)...
inline const char* const kFastCorpus[] = {"cube.poly",        "cube_cavity.poly", "l_block.poly",
                                          "schoenhardt.poly", "star_vertex.poly", "wedge_5deg.poly"};
// ...and the slow ones (tens of seconds: many leaves, the thesis' 1/alpha size
// dependence for the 1-degree wedge).
inline const char* const kSlowCorpus[] = {"cube_through_hole.poly", "fins.poly", "plate_holes.poly", "prongs_slot.poly",
                                          "wedge_1deg.poly"};

// Theorem 5's constant k, as measured (2026-11-30, with the separating splits
// of §4.1.7 steps 6 and 9): the smallest h(b) / (alpha h(B)) over the fast
// corpus, the geodesic models and random polyhedra seeds 1-12, 14 and 19 of
// tests/property/octree_property_test.cpp was 0.0227 (seed 6: a box 1/32 the
// size of its neighbour, alpha = 79.0 deg; without the separating splits it was
// 1/8, 0.0907: each of steps 6 and 9 splits boxes next to protected ones once
// more); seed 10 0.0496, the heat sink 0.0398 (a facet box 1/16 of a united
// vertex box, alpha = 90 deg). Seeds 13, 15-18 and 20-64 were not measured
// with the splits.
// The bound is that minimum rounded down to 0.02 (12% below), so a change that
// makes adjacent boxes relatively smaller than that fails here. The geodesic
// models (octree_geodesic_test.cpp) assert the same bound.
constexpr double kTheorem5Bound = 0.02;

// Lemma 1 (§4.2): every vertex has a united box (§4.1.3) and lies at least 1/4
// of its side from each of its facets (the thesis' h(b)/2 for a united box of
// side 2 h(b); Lemma 1 asks for 1/8 of the box size). Returns the number of
// vertices checked.
inline int expect_lemma1(const OctreeBuilder& b, const std::string& label) {
  const Domain3& d = b.domain();
  int checked = 0;
  for (std::size_t v = 0; v < d.plc.vertices.size(); ++v) {
    const Cube& c = b.vertex_box(static_cast<int>(v));
    const double side = c.hi.x - c.lo.x;
    EXPECT_GT(side, 0) << label << ": vertex " << v << " has no united box";
    if (!(side > 0)) continue;
    const Vec3 p = d.plc.vertices[v];
    const double q = side / 4;  // exact: dyadic
    EXPECT_TRUE(p.x >= c.lo.x + q && p.x <= c.hi.x - q && p.y >= c.lo.y + q && p.y <= c.hi.y - q && p.z >= c.lo.z + q &&
                p.z <= c.hi.z - q)
        << label << ": vertex " << v;
    ++checked;
  }
  return checked;
}

// Balance condition (§4.1.1) between balance-adjacent unprotected leaves: a
// leaf meeting P has no balance-adjacent neighbour more than twice its size
// unless that neighbour is protected (the thesis exempts protected boxes; the
// united vertex blocks may border boxes four times smaller). Returns the number
// of unbalanced neighbour pairs whose adjacency was checked.
inline int expect_balance(const OctreeBuilder& b, const std::string& label) {
  const OctTree& t = b.tree();
  int checked = 0;
  std::vector<std::int32_t> near;
  for (const std::int32_t n : b.leaves_by_id()) {
    if (!b.data(n).has_component) continue;
    t.neighbours(n, near);
    for (const std::int32_t m : near) {
      if (t.level(m) >= t.level(n) - 1) continue;  // only m more than twice n's size
      if (t.is_protected(m)) continue;
      ++checked;
      EXPECT_FALSE(b.balance_adjacent(m, n)) << label << ": leaves " << m << " and " << n;
    }
  }
  return checked;
}

// §4.1.7: every leaf meeting P is empty inside P, a vertex,
// edge or facet cone, or two facets of an edge lying outside it (never Other).
// Returns the number of leaves of each kind (indexed by LeafKind).
inline std::array<std::int64_t, kLeafKinds> expect_leaf_kinds(const OctreeBuilder& b, const std::string& label) {
  const LeafClassifier classify(b.domain());
  std::array<std::int64_t, kLeafKinds> count{};
  for (const std::int32_t n : b.leaves_by_id()) {
    const LeafFaces f = leaf_faces(b, n);
    const LeafKind k = classify.classify(f).kind;
    ++count[static_cast<std::size_t>(k)];
    EXPECT_NE(k, LeafKind::Other) << label << ": leaf " << n << " (level " << b.tree().level(n) << ", "
                                  << f.vertices.size() << " vertices, " << f.edges.size() << " edges, "
                                  << f.facets.size() << " facets, vertex_owner " << f.vertex_owner << ")";
  }
  return count;
}

// §4.1.4 / §4.1.5 (the separating splits of §4.1.7 steps 6 and 9): a leaf b
// outside the vertex boxes is balance-adjacent to boxes holding at most one P
// edge ("if b is balance-adjacent to a box b' containing an edge E, then b cannot
// be balance-adjacent to a box containing any other edge E'"), and to at most
// one facet cone apex. Edge boxes here: leaves holding an edge outside the united
// vertex boxes; facet boxes: leaves holding only facets, protected by the facet
// step (not next to an edge or vertex box, which the thesis exempts). b's own
// faces count as well. Pairs of faces sharing a P vertex are exempt (the 2D rule
// of edge_crowded / facet_crowded lets such faces approach each other outside
// the vertex boxes). Returns the number of leaves checked.
struct SeparationCount {
  int checked = 0, edge_pairs_sharing = 0, facet_pairs_sharing = 0;
};
inline SeparationCount expect_separation(const OctreeBuilder& b, const std::string& label) {
  const Domain3& d = b.domain();
  const OctTree& t = b.tree();
  auto facet_has = [&](int f, int v) {
    for (const auto& loop : d.plc.facets[static_cast<std::size_t>(f)].loops)
      for (const int w : loop)
        if (w == v) return true;
    return false;
  };
  auto facets_share = [&](int f, int g) {
    for (const auto& loop : d.plc.facets[static_cast<std::size_t>(f)].loops)
      for (const int w : loop)
        if (facet_has(g, w)) return true;
    return false;
  };
  auto outside_vertex_boxes = [&](std::int32_t n) {
    const NodeData3& nd = b.data(n);
    return nd.has_component && nd.vertices.empty() && nd.vertex_owner < 0;
  };
  auto facet_box = [&](std::int32_t n) {
    const NodeData3& nd = b.data(n);
    return outside_vertex_boxes(n) && nd.edges.empty() && !nd.facets.empty() && b.protected_by(n) == OctPhase::Facet;
  };
  SeparationCount count;
  std::vector<std::int32_t> near;
  for (const std::int32_t n : b.leaves_by_id()) {
    if (!outside_vertex_boxes(n)) continue;
    ++count.checked;
    std::vector<int> edges = b.data(n).edges;
    std::vector<int> facets;
    if (facet_box(n)) facets = b.data(n).facets;
    t.neighbours(n, near);
    for (const std::int32_t m : near) {
      if (!outside_vertex_boxes(m)) continue;
      const bool edge_box = !b.data(m).edges.empty();
      if (!edge_box && !facet_box(m)) continue;
      if (!(t.level(m) <= t.level(n) ? b.balance_adjacent(m, n) : b.balance_adjacent(n, m))) continue;
      auto& into = edge_box ? edges : facets;
      const auto& from = edge_box ? b.data(m).edges : b.data(m).facets;
      into.insert(into.end(), from.begin(), from.end());
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::sort(facets.begin(), facets.end());
    facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const DomainEdge& e = d.edges[static_cast<std::size_t>(edges[i])];
        const DomainEdge& g = d.edges[static_cast<std::size_t>(edges[j])];
        const bool shares = e.a == g.a || e.a == g.b || e.b == g.a || e.b == g.b;
        count.edge_pairs_sharing += shares ? 1 : 0;
        EXPECT_TRUE(shares) << label << ": leaf " << n << " is balance-adjacent to edges " << edges[i] << " and "
                            << edges[j];
      }
    for (std::size_t i = 0; i < facets.size(); ++i)
      for (std::size_t j = i + 1; j < facets.size(); ++j) {
        const bool shares = facets_share(facets[i], facets[j]);
        count.facet_pairs_sharing += shares ? 1 : 0;
        EXPECT_TRUE(shares) << label << ": leaf " << n << " is balance-adjacent to facet cones " << facets[i]
                            << " and " << facets[j];
      }
  }
  return count;
}

inline std::string kinds_summary(const std::array<std::int64_t, kLeafKinds>& count) {
  std::string s;
  for (int k = 0; k < kLeafKinds; ++k)
    s += std::string(k ? ", " : "") + to_string(static_cast<LeafKind>(k)) + " " +
         std::to_string(count[static_cast<std::size_t>(k)]);
  return s;
}

}  // namespace pqmesh::mv3d::octest
