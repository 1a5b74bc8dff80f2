#pragma once
// Insertion order guard for the Delaunay phase (internal).
//
// Point location walks from the latest triangle, which is fast only when
// consecutive points are close (the quadtree mesher passes z-order). For an
// incoherent order (e.g. random) the walks cost O(sqrt n) each. This guard
// measures the L1 length of the input tour, a construction used only to pick
// an order (never a geometric decision, so exactness is unaffected), and when
// it is far above what a space-filling curve gives, returns the z-order
// (Morton order over the bounding square) of the point ids; otherwise an
// empty vector meaning "keep the input order". Deterministic either way.
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh::cdt2d::detail {

std::vector<int> insertion_order(const std::vector<Vec2>& pts);

}  // namespace pqmesh::cdt2d::detail
