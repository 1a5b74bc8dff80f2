#pragma once
// Turning one TetGen facet (several closed polygons plus facet hole points)
// into Facet3s with an outer loop and hole loops.
//
// All polygons lie in one plane; decisions use exact point-in-polygon tests in
// the coordinate projection that drops the dominant axis of the facet's normal.
//  * A facet hole point marks as a hole the innermost polygon containing it
//    (the one every other containing polygon encloses).
//  * Every polygon that is not a hole bounds a piece of the facet: it becomes a
//    Facet3 whose hole loops are the polygons it directly encloses (the
//    innermost non-hole encloser of a polygon is its parent). An inner polygon
//    without a hole point is therefore both a hole of its parent and a facet of
//    its own: together they tile the facet, as TetGen reads such a facet.
//    Non-nested polygons (a facet tiled by several polygons) each become a
//    Facet3 with the facet's marker.
//  * Q is enclosed by P when no vertex of Q lies strictly outside P and some
//    vertex of Q (or, when all lie on P's boundary, some edge midpoint, a double
//    construction) lies strictly inside P.
#include <string>
#include <vector>

#include "pqmesh/plc.hpp"

namespace pqmesh::detail {

// Returns an empty message on success; otherwise a description of why the
// polygons cannot be read as a facet (the caller reports it as Unsupported).
std::string split_tetgen_facet(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& polygons,
                               const std::vector<Vec3>& hole_points, int marker, std::vector<Facet3>& out);

}  // namespace pqmesh::detail
