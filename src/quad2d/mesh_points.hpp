#pragma once
// The vertices of the 2D mesh, taken from the finished quadtree (thesis §4.3
// "Warping" and §4.4 in two dimensions; docs/algorithm/quad2d.md "Mesh vertices
// and warping", "Triangulating the boxes"):
//   * the input vertices;
//   * every leaf corner of a component that is far from ∂P and inside P;
//   * warping: a corner closer than h/4 to an input edge (h: the smallest leaf
//     at that corner) is moved to its nearest point on the edge, one copy per
//     edge (so duplicates on the two sides of a narrow slot get their own copy,
//     Fig. 4.7's "separate copies per duplicate");
//   * where an input edge crosses a box side between two corners neither of
//     which was warped onto it, the crossing point.
// Corners strictly inside the protected box of an input vertex (§4.1.3) are
// left out, as if the box had been united (Lemma 1: the vertex is then at
// least h/2 from every other vertex of its box).
//
// Points on a slanted input edge are stored as roundings that pass
// within_ulp_of_segment (predicates.hpp), the rule the checker applies.
#include <vector>

#include "pqmesh/quadmesh.hpp"
#include "pqmesh/vec.hpp"
#include "quad2d/quadtree_builder.hpp"

namespace pqmesh::quad2d {

struct MeshPoints {
  std::vector<Vec2> points;       // distinct, sorted by (x, y)
  std::vector<int> input_vertex;  // per point: the input vertex id, or -1
  // Per input segment, the ids of the points on it ordered from segments[s][0]
  // to segments[s][1], both ends included.
  std::vector<std::vector<int>> segment_chain;
};

MeshPoints generate_points(const QuadtreeBuilder& builder, QuadMeshStats& stats);

}  // namespace pqmesh::quad2d
