#pragma once
// Exact geometry against the shifted box C_e of cube_components.hpp:
// axis-parallel lines with perturbed fixed coordinates ("K lines", probes,
// rays) against facet triangles, segments against the faces of C_e, and the
// triangles meeting C_e. Every decision is the sign of a detail::Pert.
#include <array>

#include "mv3d/cube_components.hpp"
#include "mv3d/perturbed.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::mv3d::detail {

inline double at(Vec3 p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }
inline double lo_of(const Cube& c, int axis) { return at(c.lo, axis); }
inline double hi_of(const Cube& c, int axis) { return at(c.hi, axis); }

// The shifted plane of C_e: axis k at lo_k - e^(k+1) (side 0) or hi_k + e^(k+1) (side 1).
Pert plane(const Cube& c, int axis, int side);

// In C_e  <=>  in the closed box C (the shift is outward).
bool vertex_inside(Vec3 p, const Cube& c);

// sign(v - a) for a double v (exact).
int side_sign(double v, const Pert& a);

// An axis-parallel line: direction axis d, fixed coordinates f1 on axis
// (d + 1) % 3 and f2 on axis (d + 2) % 3; lo/hi bracket the constant parts
// of f1, f2 by doubles (lo <= c0 <= hi) for the exact filter in line_hit.
struct Line {
  int d = 0;
  Pert f1, f2;
  std::array<double, 2> lo{}, hi{};
};
Line make_line(int d, Pert f1, Pert f2);

// Does the line cross the closed triangle abc (oriented outward)? The line
// must be generic (cube_components.cpp): it crosses the plane in one point
// (or is parallel to it) and that point is strictly inside or strictly
// outside the triangle (InternalError otherwise). pos: coordinate along d;
// entering: moving in +d enters P.
bool line_hit(const Line& l, Vec3 a, Vec3 b, Vec3 c, Pert& pos, bool& entering);

// Does segment uv cross the face of C_e on plane (axis, side) inside the
// face? Then *w (if given) receives the crossing point.
bool segment_crosses_face(Vec3 u, Vec3 v, const Cube& c, int axis, int side, std::array<Pert, 3>* w);

// Does the closed segment uv meet C_e?
bool segment_meets(Vec3 u, Vec3 v, const Cube& c);

// Cube edge index d * 4 + s1 * 2 + s2: direction d, side s1 on axis
// (d + 1) % 3, s2 on axis (d + 2) % 3.
Line cube_edge_line(const Cube& c, int e);

// Corner id: bit k = side on axis k. The start (end = 0, side 0 along d) or
// end of edge e.
int edge_corner(int e, int end);

// Does facet triangle t meet C_e? edge_lines[e] = cube_edge_line(c, e).
bool triangle_meets(const Domain3& dom, int t, const Cube& c, const std::array<Line, 12>& edge_lines);

}  // namespace pqmesh::mv3d::detail
