#pragma once
// The minimum dihedral angle of a tetrahedron alone, for callers that test
// many candidate shapes against a floor and need the full quality
// (tetrahedron_quality, with its costlier minimal enclosing ball) only for
// the few that pass (improve3d's smoothing).
#include "predicates/predicates.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {

// tetrahedron_quality(a, b, c, d).min_dihedral_deg, the same double bit for
// bit (simplex_quality.cpp: the same normals and keys; only the angles that
// can be the largest angle between face normals are evaluated). A flat
// tetrahedron (exact orientation Zero) gives 0. Cost: one orient3d, four cross
// products, six dot products and one or two atan2 calls.
double tetrahedron_min_dihedral(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
// The same for a caller that knows orientation == orient3d(a, b, c, d) (saves that predicate).
double tetrahedron_min_dihedral(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign orientation);

}  // namespace pqmesh
