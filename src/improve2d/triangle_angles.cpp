#include "improve2d/triangle_angles.hpp"

#include <algorithm>

namespace pqmesh::detail {

double min_angle(Vec2 a, Vec2 b, Vec2 c) {
  return std::min({angle_between(b - a, c - a), angle_between(c - b, a - b), angle_between(a - c, b - c)});
}

}  // namespace pqmesh::detail
