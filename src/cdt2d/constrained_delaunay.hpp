#pragma once
// Constrained Delaunay triangulation of a planar point set with directed
// constraint edges (thesis §2.1 recalls the CDT and Lawson's angle optimality;
// the 2D meshers use it to triangulate point sets produced by the quadtree).
//
// Algorithm (details and invariants in triangulation.hpp):
//   1. Delaunay triangulation by incremental insertion with Lawson flips, in
//      rounds of decreasing stride over the input order (every 8^k-th point
//      first; each round keeps the input order). Point location walks from
//      the most recently created triangle, so spatially coherent orders
//      (z-order) are fast; an incoherent input order (detected by the length
//      of its tour, insertion_order.hpp) is replaced by a z-order. The convex
//      hull is closed by a ghost vertex: every hull edge carries a ghost
//      triangle, so points outside the current hull need no special case.
//   2. Each constraint is inserted by edge flips (Sloan 1993) across the
//      edges it crosses, then the Delaunay property is restored by Lawson
//      flips of the new non-constraint edges. A constraint that is already an
//      edge (the common case for consecutive points of a chain) only costs
//      one rotation around its first vertex.
//   3. keep_inside: flood fill from the left side of every constraint.
//
// Exactness and ties: every decision is an exact predicate (orient2d,
// incircle, dot_sign from src/predicates). An edge is flipped only when the
// opposite vertex is strictly inside the circumcircle (incircle > 0); ties
// (cocircular points, incircle == 0) never flip. The result is therefore one
// of the constrained Delaunay triangulations: every non-constraint interior
// edge satisfies incircle <= 0 with its opposite vertex, and which one of the
// equivalent triangulations of a cocircular set comes out depends only on the
// input (points in their order, constraints in theirs): the output, triangles
// in internal slot order, is deterministic.
//
// Constraints through points: a constraint that passes exactly through
// another input point (exactly collinear, strictly between its ends) is split
// there; both parts become constrained edges with the original direction.
// Overlapping collinear constraints are therefore allowed. For keep_inside, a
// constraint given in both directions (a -> b and b -> a) is an interior
// edge: the inside lies on both of its sides.
//
// Errors (pqmesh::InternalError, the caller's invariants are broken):
//   - two input points with identical coordinates;
//   - a constraint with an id out of range or with equal ends;
//   - two constraints that cross at a point interior to both;
//   - keep_inside only: a triangle reached by the inside flood fill that lies
//     on the right of some constraint (reached from both sides), or an inside
//     region that is unbounded (the fill leaves the convex hull).
//
// Degenerate sizes: fewer than three points, or all points on one line, give
// no triangles (after the duplicate check); keep_inside without constraints
// keeps nothing. At most 2^27 points (half-edge ids are ints).
#include <array>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh::cdt2d {

struct CdtInput {
  std::vector<Vec2> points;                     // distinct (exact coordinates)
  std::vector<std::array<int, 2>> constraints;  // directed edges between point ids; the region to keep lies on the LEFT
};

struct CdtOutput {
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise (orient2d > 0)
};

// keep_inside = true: only the triangles on the left of the constraint loops
// (flood fill through non-constraint edges starting from the left side of
// every constraint); false: the whole convex hull.
CdtOutput constrained_delaunay(const CdtInput& in, bool keep_inside);

}  // namespace pqmesh::cdt2d
