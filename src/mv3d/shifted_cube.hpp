#pragma once
// Exact geometry against the shifted box C_e of cube_components.hpp:
// axis-parallel lines with perturbed fixed coordinates ("K lines", probes,
// rays) against facet triangles, segments against the faces of C_e, and the
// triangles meeting C_e. Every decision is the sign of a detail::Pert.
// Cost: a Pert holds six GMP rationals, so decisions first try exact double
// predicates (orient2d, orient3d of predicates.hpp) on the constant parts and
// build Perts only when the constant parts tie (Pos below).
#include <array>
#include <memory>
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
// brackets are disjoint compare by the brackets; otherwise they compare
// exactly (a plane-kind Pos never needs its Pert: its coefficients are known).
// Kinds: a double plus s * term (a shifted plane), a given Pert, or the
// crossing of a Line with a triangle (computed only when a tie needs it).
// The exact value is shared and immutable once made, so copying or moving a
// Pos (events, lines, junctions) never copies rationals.
struct Line;
struct Pos {
  double lo = 0, hi = 0;
  // lazily filled exact value (never modified once set)
  mutable std::shared_ptr<const Pert> exact;
  // plane kind: value lo (== hi), term, sign; crossing kind: line, triangle
  int term = -1, sgn = 0;
  bool given = false;  // made by of_pert
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
  // Plane kind (a double plus s * term): coefficients known without a Pert.
  bool plane_kind() const { return line == nullptr && !given; }
  // The sign of coefficient k >= 1 (exact; no Pert made for the plane kind).
  int coefficient_sign(int k) const;
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
// face? Then *w (if given) receives coordinate (axis + 2) % 3 of the crossing
// point (the fixed coordinate of the probe through it, cube_components.cpp).
bool segment_crosses_face(Vec3 u, Vec3 v, const Cube& c, int axis, int side, Pert* w);

// Does the closed segment uv meet C_e? (Exact double filters first.)
bool segment_meets(Vec3 u, Vec3 v, const Cube& c);

// Cube edge index d * 4 + s1 * 2 + s2: direction d, side s1 on axis
// (d + 1) % 3, s2 on axis (d + 2) % 3.
Line cube_edge_line(const Cube& c, int e);

// Corner id: bit k = side on axis k. The start (end = 0, side 0 along d) or
// end of edge e.
int edge_corner(int e, int end);

// The 12 edge lines of C_e (cube_edge_line), made on first use: most
// triangles are decided before any edge line is needed.
class EdgeLines {
 public:
  explicit EdgeLines(const Cube& c) : cube_(c) {}
  const std::array<Line, 12>& get() {
    if (!made_) {
      for (int e = 0; e < 12; ++e) lines_[static_cast<std::size_t>(e)] = cube_edge_line(cube_, e);
      made_ = true;
    }
    return lines_;
  }

 private:
  Cube cube_;
  bool made_ = false;
  std::array<Line, 12> lines_{};
};

// Does facet triangle t meet C_e? edge_lines: those of c.
bool triangle_meets(const Domain3& dom, int t, const Cube& c, EdgeLines& edge_lines);

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
