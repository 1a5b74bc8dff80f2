// alpha for a 2D polygon with holes: the smallest interior corner angle
// (thesis ch. 3: "This is also how we define interior angle in two
// dimensions"). The corner turn is exact (orient2d); the angle value is a
// construction (atan2 via angle_between).
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "pqmesh/alpha.hpp"
#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {

AlphaResult compute_alpha(const std::vector<Vec2>& vertices, const std::vector<std::vector<int>>& loops) {
  AlphaResult best;
  best.radians = std::numeric_limits<double>::infinity();
  best.kind = "edge-edge";
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& L = loops[l];
    const std::size_t n = L.size();
    if (n < 3)
      throw DomainError(ErrorCode::InvalidPolygon, "loop " + std::to_string(l) + " has fewer than 3 vertices");
    for (int id : L)
      if (id < 0 || id >= int(vertices.size()))
        throw DomainError(ErrorCode::InvalidPolygon,
                          "loop " + std::to_string(l) + " refers to missing vertex " + std::to_string(id), {id});
    for (std::size_t i = 0; i < n; ++i) {
      // Interior on the left of a -> v -> b: the angle runs counter-clockwise
      // from ray v->b to ray v->a.
      const int a = L[(i + n - 1) % n], v = L[i], b = L[(i + 1) % n];
      const Vec2 A = vertices[a], P = vertices[v], B = vertices[b];
      const double phi = angle_between(B - P, A - P);
      double angle = std::numbers::pi;
      switch (orient2d(A, P, B)) {
        case Sign::Positive: angle = phi; break;
        case Sign::Negative: angle = 2 * std::numbers::pi - phi; break;
        case Sign::Zero:
          if (A == P || B == P || dot_sign(P, A, B) == Sign::Positive)
            throw DomainError(ErrorCode::InvalidPolygon,
                              "loop " + std::to_string(l) + " folds back on itself at vertex " + std::to_string(v),
                              {v});
          break;
      }
      if (angle < best.radians) {
        best.radians = angle;
        best.apex = v;
        best.first = FaceRef::edge(a, v);
        best.second = FaceRef::edge(v, b);
      }
    }
  }
  if (best.apex < 0) throw DomainError(ErrorCode::EmptyDomain, "the polygon has no loops");
  best.min_dihedral_radians = best.radians;
  return best;
}

}  // namespace pqmesh
