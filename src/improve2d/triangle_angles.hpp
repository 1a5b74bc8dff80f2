#pragma once
// Smallest angle of a triangle (floating point: a measurement, never a decision).
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

double min_angle(Vec2 a, Vec2 b, Vec2 c);

}  // namespace pqmesh::detail
