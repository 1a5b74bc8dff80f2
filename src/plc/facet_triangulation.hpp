#pragma once
// Triangulation of a planar polygon with holes without new vertices
// (ear clipping after bridging each hole to the outer boundary). Every
// decision is an exact orient2d on the (exactly projected) input points.
#include <array>
#include <vector>

#include "pqmesh/plc.hpp"

namespace pqmesh::detail {

// loops[0] is the outer boundary, loops[1..] holes, as indices into `points`;
// either turn is accepted for each loop. Preconditions (checked by facet
// validation): every loop is simple, loops do not touch one another, holes lie
// inside the outer loop and not inside one another. Returns counter-clockwise
// triangles of indices; their areas sum to the polygon's area.
// Throws InternalError if the preconditions were violated so no ear exists.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec2>& points,
                                                    std::vector<std::vector<int>> loops);

// Triangulates a validated facet in the projection dropping axis `drop`.
// The triangles (vertex ids) turn the same way as loops[0], so they share the
// facet's right-hand normal.
std::vector<std::array<int, 3>> triangulate_facet(const std::vector<Vec3>& vertices, const Facet3& facet,
                                                  int drop);

}  // namespace pqmesh::detail
