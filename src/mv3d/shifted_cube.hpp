#pragma once
// Exact geometry against the shifted box C_e of cube_components.hpp:
// axis-parallel lines with perturbed fixed coordinates ("K lines", probes,
// rays) against facet triangles, segments against the faces of C_e, and the
// triangles meeting C_e. Every decision is the sign of a detail::Pert.
// Cost: a Pert holds six GMP rationals, so decisions first try exact double
// predicates (orient2d, orient3d of predicates.hpp) on the constant parts and
// build Perts only when the constant parts tie (Pos below).
#include <array>
#include <optional>
#include <span>

#include "mv3d/cube_components.hpp"
#include "mv3d/perturbed.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::mv3d::detail {

inline double lo_of(const Cube& c, int axis) { return axis_coord(c.lo, axis); }
inline double hi_of(const Cube& c, int axis) { return axis_coord(c.hi, axis); }

// The shifted plane of C_e: axis k at lo_k - e^(k+1) (side 0) or hi_k + e^(k+1) (side 1).
Pert plane(const Cube& c, int axis, int side);

// In C_e  <=>  in the closed box C (the shift is outward).
bool vertex_inside(Vec3 p, const Cube& c);

// sign(v - a) for a double v (exact).
int side_sign(double v, const Pert& a);

// A perturbed number known by a double bracket [lo, hi] of its constant part
// (lo <= c0 <= hi, established exactly) and, on demand, exactly. Two Pos whose
// brackets are disjoint compare by the brackets; otherwise both are made exact.
// Kinds: a double plus s * term (a shifted plane), a given Pert, or the
// crossing of a Line with a triangle (computed only when a tie needs it).
struct Line;
struct Pos {
  double lo = 0, hi = 0;
  // lazily filled exact value
  mutable std::optional<Pert> exact;
  // plane kind: value lo (== hi), term, sign; crossing kind: line, triangle
  int term = -1, sgn = 0;
  const Line* line = nullptr;
  Vec3 a{}, b{}, c{};

  static Pos of_double(double v, int term = -1, int s = 0) {
    Pos p;
    p.lo = p.hi = v;
    p.term = term;
    p.sgn = s;
    return p;
  }
  static Pos of_pert(Pert v);
  const Pert& value() const;
};
// sign(x - y)
int compare(const Pos& x, const Pos& y);
// The shifted plane of C_e as a Pos.
Pos plane_pos(const Cube& c, int axis, int side);

// An axis-parallel line: direction axis d, fixed coordinates f1 on axis
// (d + 1) % 3 and f2 on axis (d + 2) % 3; lo/hi bracket the constant parts
// of f1, f2 by doubles (lo <= c0 <= hi) for the exact filter in line_hit.
struct Line {
  int d = 0;
  Pos f1, f2;
  std::array<double, 2> lo{}, hi{};
};
Line make_line(int d, Pos f1, Pos f2);

// Does the line cross the closed triangle abc (oriented outward)? The line
// must be generic (cube_components.cpp): it crosses the plane in one point
// (or is parallel to it) and that point is strictly inside or strictly
// outside the triangle (InternalError otherwise). pos: coordinate along d;
// entering: moving in +d enters P.
// The Pos refers to l (lazily): l must outlive it.
bool line_hit(const Line& l, Vec3 a, Vec3 b, Vec3 c, Pos& pos, bool& entering);

// Does segment uv cross the face of C_e on plane (axis, side) inside the
// face? Then *w (if given) receives the crossing point.
bool segment_crosses_face(Vec3 u, Vec3 v, const Cube& c, int axis, int side, std::array<Pert, 3>* w);

// Does the closed segment uv meet C_e? (Exact double filters first.)
bool segment_meets(Vec3 u, Vec3 v, const Cube& c);

// Cube edge index d * 4 + s1 * 2 + s2: direction d, side s1 on axis
// (d + 1) % 3, s2 on axis (d + 2) % 3.
Line cube_edge_line(const Cube& c, int e);

// Corner id: bit k = side on axis k. The start (end = 0, side 0 along d) or
// end of edge e.
int edge_corner(int e, int end);

// Does facet triangle t meet C_e? edge_lines[e] = cube_edge_line(c, e).
bool triangle_meets(const Domain3& dom, int t, const Cube& c, const std::array<Line, 12>& edge_lines);

// A point with perturbed coordinates, e.g. a corner of C_e.
using PPoint = std::array<Pos, 3>;
// Corner k (bit j = side on axis j) of C_e.
PPoint corner_point(const Cube& c, int k);
// Is `to` in P, given that `from` is (from_in)? Walks the axis-parallel path
// from -> (to.x, from.y, from.z) -> (to.x, to.y, from.z) -> to, counting its
// crossings with the triangles `tris`, which must contain every facet
// triangle meeting the path (e.g. both points in a box C_e and tris those
// meeting it). Each leg's two fixed coordinates must carry distinct
// infinitesimal terms and no path vertex may lie on a triangle plane (true
// for corners of shifted boxes, and for the mark points of components()).
bool walk_status(const Domain3& dom, std::span<const int> tris, const PPoint& from, bool from_in, const PPoint& to);

}  // namespace pqmesh::mv3d::detail
