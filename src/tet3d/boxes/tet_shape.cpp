#include "tet3d/boxes/tet_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pqmesh::tet3d {

double tet_shape(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double volume6 = dot(cross(b - a, c - a), d - a);
  if (!(volume6 > 0)) return std::numeric_limits<double>::infinity();
  // Twice the total face area; inradius = 3 V / area = volume6 / area2.
  const double area2 = norm(cross(b - a, c - a)) + norm(cross(b - a, d - a)) + norm(cross(c - a, d - a)) +
                       norm(cross(c - b, d - b));
  const double longest = std::max({norm(b - a), norm(c - a), norm(d - a), norm(c - b), norm(d - b), norm(d - c)});
  return longest * area2 / volume6;
}

}  // namespace pqmesh::tet3d
