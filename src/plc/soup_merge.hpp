#pragma once
// Merging a polygon soup (STL, OFF, OBJ, Medit surfaces) into planar facets.
//
// Rules (see soup_merge.cpp for the details and why each decision is exact):
//  * Two polygons are neighbours across an edge when that edge (as an unordered
//    vertex pair) is used by exactly those two polygons and they traverse it in
//    opposite directions (consistent orientation).
//  * Exact merge: neighbours with equal markers whose vertices are all exactly
//    coplanar (orient3d == 0 against the seed polygon's plane) and that face the
//    same way (exact orientation of each polygon in the seed's projection plane)
//    join one group. Groups grow by breadth-first search from the lowest
//    unassigned polygon index, so groups and output are deterministic.
//  * Each group becomes one Facet3: boundary edges (edges not shared with a
//    neighbour inside the group) are chained into loops; at a vertex where the
//    boundary touches itself the chain takes the sharpest turn towards the
//    facet interior (which separates two pieces touching at a vertex), and a
//    closed walk that still passes a vertex twice (a hole touching the outer
//    boundary) is split there into simple cycles. The unique
//    loop turning the same way as the polygons is loops[0]; the others (turning
//    the other way) are holes. Loops keep the polygons' orientation. When this
//    fails (a loop repeats a vertex, no or several outer loops, an open chain),
//    the group's polygons are emitted as separate facets.
//  * Near merge (merge_angle_degrees > 0): adjacent exact groups with equal
//    markers whose normals are within the angle of the seed group's normal are
//    joined, but only when the result is exactly planar without moving any
//    vertex another facet uses: either the vertices on the merged loops are
//    already exactly coplanar (vertices strictly inside the group disappear
//    from the facet), or none of the loop vertices is used outside the group and
//    snapping them onto a plane (see snap_to_plane in soup_merge.cpp) yields
//    exactly coplanar points. Otherwise the exact groups stay separate.
#include <vector>

#include "pqmesh/plc.hpp"

namespace pqmesh::detail {

struct PolygonSoup {
  std::vector<Vec3> vertices;
  std::vector<int> offsets{0};  // polygon p uses indices[offsets[p] .. offsets[p+1])
  std::vector<int> indices;     // vertex ids
  std::vector<int> markers;     // one per polygon
  int polygon_count() const { return static_cast<int>(offsets.size()) - 1; }
  int polygon_size(int p) const { return offsets[p + 1] - offsets[p]; }
};

struct SoupMergeResult {
  std::vector<Facet3> facets;
  std::vector<int> first_polygon;  // lowest input polygon index of each facet
  int merged_exact = 0;  // sum over exact groups of (polygons - 1)
  int merged_near = 0;   // sum over accepted near groups of (exact groups - 1)
};

// Merges `soup` (vertices of free loop vertices may be moved by a near merge).
// Facets are ordered by first_polygon.
SoupMergeResult merge_soup(PolygonSoup& soup, double merge_angle_degrees);

// One facet per polygon, no merging.
SoupMergeResult soup_without_merging(const PolygonSoup& soup);

}  // namespace pqmesh::detail
