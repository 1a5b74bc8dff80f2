#pragma once
// Whether a tetrahedron's aspect ratio is within a limit, for callers that
// test many candidate shapes against a limit and need the full quality
// (tetrahedron_quality) only for the shape they keep (improve3d's smoothing).
#include "predicates/predicates.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

// tetrahedron_quality(a, b, c, d).aspect_ratio <= limit, the same answer
// bit for bit, for a caller that knows orientation == orient3d(a, b, c, d).
// The minimal enclosing ball is computed only when the sphere ratio
// (circumradius / inradius, never below the aspect ratio) exceeds the limit;
// no dihedral angle is computed. Cost: four cross products and, for a shape
// whose circumcentre lies far enough outside it, the enclosing-ball search.
bool tetrahedron_aspect_within(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign orientation, double limit);

}  // namespace pqmesh
