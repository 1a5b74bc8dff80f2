#pragma once
// Theorem 5 of the thesis (§4.2): for a box B whose embedding contains a point
// of P and a box b adjacent to it, h(b) >= k * alpha * h(B), k a constant and
// alpha the smallest interior angle of P (pqmesh/alpha.hpp). This module
// measures the left-hand side over a finished octree: the smallest
//     h(b) / (alpha * h(B))  over adjacent pairs with h(b) <= h(B),
// i.e. the best k for this input, and the pair that achieves it.
//
// Definitions used (documented here because the thesis' adjacency, a common
// point of P ∧ b and P ∧ B, is not something the octree stores):
//   * a "box" is a leaf meeting P, except that the leaves of a vertex's united
//     box (vertex_owner = v, §4.1.3) stand for that united box: their h is the
//     side of vertex_box(v) (2 h(b) of the vertex leaf b), as the thesis' B is
//     one protected box; pairs inside one united box are skipped;
//   * two leaves are adjacent when they are neighbours (Tree<3>: closed cubes
//     meet, open cubes disjoint, not duplicates of one another), their closed
//     cubes share a portion of a box facet of positive area (two axes overlap
//     with positive length, the third touches), and they are balance-adjacent
//     (OctreeBuilder::balance_adjacent: P ∧ small ⊂ P ∧ ex(big)). The last
//     condition drops pairs facing each other across a thin gap outside P,
//     whose components are far apart inside P; every pair adjacent in the
//     thesis' sense (a shared point of P) is balance-adjacent, so the measured
//     minimum is at most the thesis' one.
// Every comparison of box planes is exact (dyadic doubles); the ratio itself
// is a double computed for the report only.
#include <cstdint>
#include <limits>

#include "mv3d/octree_builder.hpp"

namespace pqmesh::mv3d {

struct SizeRatioReport {
  double alpha = 0;        // radians, as given
  std::int64_t pairs = 0;  // adjacent pairs examined
  // The minimum of h(b) / (alpha h(B)) and its pair: leaf ids, with the sides
  // used (united-box sides for united-box pieces).
  double min_ratio = std::numeric_limits<double>::infinity();
  std::int32_t small = -1, big = -1;
  double h_small = 0, h_big = 0;
  // The smallest plain size ratio h(b) / h(B) (not divided by alpha).
  double min_plain = std::numeric_limits<double>::infinity();
};

// alpha: pqmesh::compute_alpha(builder.domain().plc).radians (or any positive
// angle). Cost: one neighbour query per leaf meeting P plus one balance-
// adjacency query per face-sharing pair (cached extended components).
SizeRatioReport size_ratio(const OctreeBuilder& builder, double alpha);

// The same with alpha computed from the builder's domain.
SizeRatioReport size_ratio(const OctreeBuilder& builder);

}  // namespace pqmesh::mv3d
