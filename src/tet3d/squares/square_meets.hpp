#pragma once
// Exact incidence of P faces with a closed, prewarped box-face square S
// (thesis §4.4: "the cases depend on which P faces pass through the facet").
// Used by the square dispatcher (square_cases.hpp) to decide which faces of a
// box's component meet S; both boxes sharing S then see the same set.
//
// S lies in the plane x_n = c (an exact double, a box plane) and spans the
// closed rectangle [u0, u1] x [v0, v1] of its in-plane axes. Every decision is
// an exact predicate on input doubles:
//   * the side of a point against S's plane: compare(p_n, c);
//   * an in-plane coordinate w* of the crossing of segment xy with the plane
//     against a bound w0: sign(w* - w0) = -orient2d((x_n, x_w), (y_n, y_w),
//     (c, w0)) · sign(y_n - x_n) (the crossing is never constructed);
//   * the side of a corner of S against a triangle's plane: orient3d.
// A segment meets the rectangle iff no separating axis exists among u, v and
// the segment's normal (separating-axis theorem for two convex sets); a
// triangle crossing the plane meets it in such a segment, whose normal side
// of a corner is the corner's side of the triangle's plane. A triangle lying
// in the plane is tested in 2D with the axes u, v and its three side normals.
#include <array>

#include "pqmesh/vec.hpp"
#include "tet3d/squares/box_faces.hpp"

namespace pqmesh::tet3d {

struct SquareGeometry {
  int n = 0, u = 1, v = 2;
  double c = 0, u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  std::array<Vec3, 4> corners;  // counter-clockwise about +n
};

SquareGeometry square_geometry(const FaceSquare& s, const OctTree& tree);

// The closed square contains p.
bool square_contains(const SquareGeometry& g, Vec3 p);
// The closed segment ab meets the closed square.
bool segment_meets_square(const SquareGeometry& g, Vec3 a, Vec3 b);
// The closed triangle abc meets the closed square.
bool triangle_meets_square(const SquareGeometry& g, Vec3 a, Vec3 b, Vec3 c);

}  // namespace pqmesh::tet3d
