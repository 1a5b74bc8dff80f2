#pragma once
// Re-triangulation of a cavity without its inner vertices, for the 2D quality
// pass (quality_pass.hpp; docs/algorithm/improve2d.md "The pass").
//
// A cavity is a set of triangles of a conforming mesh that is connected
// across edges; its union may have holes (input holes of P, or mesh triangles
// it surrounds) and pinched vertices. Its boundary is the set of directed
// edges a -> b of its (counter-clockwise) triangles whose other side is not in
// the cavity, so the cavity lies on the LEFT of each. The re-triangulation is
// the constrained Delaunay triangulation of the boundary vertices with those
// edges as constraints, kept on their left (cdt2d, exact predicates): by
// Lawson's theorem (thesis §2.1) it has the largest min angle among all
// triangulations of the cavity with those vertices, and its boundary edges are
// the cavity's, so the rest of the mesh stays conforming.
#include <array>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// `boundary`: the cavity's directed boundary edges (global vertex ids into
// `points`); `inner_vertices`: the number of vertices strictly inside the
// cavity (they are dropped). Returns the new triangles (global ids, counter-
// clockwise), or an empty vector when the CDT fails or does not cover exactly
// the cavity: its triangle count must be the cavity's minus 2 per dropped
// inner vertex (Euler's formula with the boundary unchanged).
std::vector<std::array<int, 3>> retriangulate_cavity(const std::vector<Vec2>& points,
                                                     const std::vector<std::array<int, 2>>& boundary,
                                                     std::size_t cavity_triangles, std::size_t inner_vertices);

}  // namespace pqmesh::detail
