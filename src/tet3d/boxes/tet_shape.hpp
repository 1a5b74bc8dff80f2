#pragma once
// A shape measure of a tetrahedron for choosing between decompositions
// (the edge box's apex on E, edge_box.cpp): the longest edge over the
// inradius (3 V / total face area), within a constant factor of the aspect
// ratio of pqmesh/quality.hpp. +infinity unless (a, b, c, d) has positive
// volume in floating point. Only compared, never a validity decision (those
// are exact orient3d).
#include "pqmesh/vec.hpp"

namespace pqmesh::tet3d {

double tet_shape(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

}  // namespace pqmesh::tet3d
