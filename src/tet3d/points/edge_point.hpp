#pragma once
// Points constructed on a P edge (thesis §4.5.3: the central vertex of an edge
// box is the midpoint of E ∩ I(b)). As for points on facets (facet_plane.hpp),
// the exact point has in general no double coordinates; it is stored as a
// double point p with within_ulp_of_segment(p, a, b)
// (docs/algorithm/tet3d_boxes.md "Exactness"), the rule by which the checker
// accepts it on E.
#include <utility>

#include "pqmesh/vec.hpp"

namespace pqmesh::tet3d {

// The parameter interval [t0, t1] of the segment a + t (b - a), t in [0, 1],
// inside the closed axis-aligned box [lo, hi] (a construction; t0 > t1 when
// the segment misses the box).
std::pair<double, double> clip_segment(Vec3 a, Vec3 b, Vec3 lo, Vec3 hi);

// A double point within an ulp of the segment ab (a != b), near m: m's
// coordinate on the segment's dominant axis d is kept (clamped to the
// segment's range), and each other coordinate is the largest double not
// beyond the segment's exact coordinate at that d, found by bisection decided
// by exact orient2d. Throws InternalError if the result fails
// within_ulp_of_segment (not expected: the exact point lies in the ulp box).
Vec3 round_onto_segment(Vec3 a, Vec3 b, Vec3 m);

}  // namespace pqmesh::tet3d
