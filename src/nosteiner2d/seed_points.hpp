#pragma once
// Seed points of the seeded refined candidates (docs/algorithm/nosteiner2d.md
// "Refined candidates"): interior points placed where the upper bound says
// the best triangles must be, before Delaunay refinement (which cannot find
// them: near a segment facing a close obstacle, or in a corner whose sides
// differ much in length, its new points fall outside P and are given up).
//
//   - Segment apex: for each side ab whose segment bound t*(ab)
//     (segment_bound.hpp) is below the target, with t = min(t*(ab), alpha_a,
//     alpha_b) (the sides at a and b are not in t*), the apex of the
//     isosceles triangle on ab with base angles t / 2. It is kept when it is
//     strictly left of ab and its computed max(angle pab, angle pba) is at
//     most 3/4 t: then it lies in the open isosceles triangle of base angles
//     t, which meets no point of dP, so it is strictly inside P.
//   - Fan spokes: for each input vertex V whose fan bound A (fan_bound.hpp)
//     is below the target, the k - 1 inner spoke ends of the fan of k =
//     clamp(floor(alpha_V / A), 1, 64) equal angles whose spoke lengths grow
//     geometrically from one side's length to the other's (the equal split
//     the bound's proof shows best). Each is kept when locate() puts it
//     strictly inside P (exact).
//   - Obstacle spokes (with `obstacles`): for each side E of V and vertex q of dP in V's closed
//     sector with |Vq| < |E| whose obstacle fan bound A is below the target,
//     the inner spoke ends of k = clamp(floor(omega / A), 1, 64) equal angles
//     up to q's direction, lengths geometric from |E| to |Vq|; located too.
//   At most 4096 located points in all.
// Sorted and duplicates removed (a deterministic order: by x, then y).
// Cost: the segment bound plus O(n) per located point.
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// The segment apexes and fan spokes, and with `obstacles` the obstacle spokes too.
std::vector<Vec2> seed_points(const Domain2& domain, double target_degrees, bool obstacles);

}  // namespace pqmesh::detail
