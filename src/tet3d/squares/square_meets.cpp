#include "tet3d/squares/square_meets.hpp"

#include <algorithm>

#include "predicates/predicates.hpp"

namespace pqmesh::tet3d {

namespace {


// A point of S's plane: an input point lying on it, or the crossing of the
// segment xy (x, y strictly on opposite sides) with it.
struct PlanePoint {
  Vec3 x, y;
  bool crossing = false;
};

// sign(w - w0) for the point's coordinate w on in-plane axis `axis`.
Sign cmp(const SquareGeometry& g, const PlanePoint& p, int axis, double w0) {
  if (!p.crossing) return compare(axis_coord(p.x, axis), w0);
  const Vec2 a{axis_coord(p.x, g.n), axis_coord(p.x, axis)}, b{axis_coord(p.y, g.n), axis_coord(p.y, axis)};
  return -(orient2d(a, b, {g.c, w0}) * compare(axis_coord(p.y, g.n), axis_coord(p.x, g.n)));
}

bool point_in(const SquareGeometry& g, const PlanePoint& p) {
  return cmp(g, p, g.u, g.u0) != Sign::Negative && cmp(g, p, g.u, g.u1) != Sign::Positive &&
         cmp(g, p, g.v, g.v0) != Sign::Negative && cmp(g, p, g.v, g.v1) != Sign::Positive;
}

// Axis-interval test of the segment pq (in the plane) against [w0, w1].
bool overlaps(const SquareGeometry& g, const PlanePoint& p, const PlanePoint& q, int axis, double w0, double w1) {
  if (cmp(g, p, axis, w0) == Sign::Negative && cmp(g, q, axis, w0) == Sign::Negative) return false;
  if (cmp(g, p, axis, w1) == Sign::Positive && cmp(g, q, axis, w1) == Sign::Positive) return false;
  return true;
}

Vec2 in_plane(const SquareGeometry& g, Vec3 p) { return {axis_coord(p, g.u), axis_coord(p, g.v)}; }

}  // namespace

SquareGeometry square_geometry(const FaceSquare& s, const OctTree& tree) {
  SquareGeometry g;
  g.n = s.n;
  g.u = s.u;
  g.v = s.v;
  GridPoint hi = s.lo;
  hi.f[s.u] += s.side;
  hi.f[s.v] += s.side;
  const Vec3 lo = grid_coordinates(tree, s.lo), up = grid_coordinates(tree, hi);
  g.c = axis_coord(lo, s.n);
  g.u0 = axis_coord(lo, s.u);
  g.u1 = axis_coord(up, s.u);
  g.v0 = axis_coord(lo, s.v);
  g.v1 = axis_coord(up, s.v);
  for (int k = 0; k < 4; ++k) {
    double p[3];
    p[s.n] = g.c;
    p[s.u] = (k == 1 || k == 2) ? g.u1 : g.u0;
    p[s.v] = (k >= 2) ? g.v1 : g.v0;
    g.corners[static_cast<std::size_t>(k)] = {p[0], p[1], p[2]};
  }
  return g;
}

bool square_contains(const SquareGeometry& g, Vec3 p) {
  return axis_coord(p, g.n) == g.c && point_in(g, {p, p, false});
}

bool segment_meets_square(const SquareGeometry& g, Vec3 a, Vec3 b) {
  const Sign sa = compare(axis_coord(a, g.n), g.c), sb = compare(axis_coord(b, g.n), g.c);
  if (sa == sb && sa != Sign::Zero) return false;
  if (sa == Sign::Zero && sb == Sign::Zero)
    return segment_meets_rect(in_plane(g, a), in_plane(g, b), {g.u0, g.v0}, {g.u1, g.v1});
  if (sa == Sign::Zero) return point_in(g, {a, a, false});
  if (sb == Sign::Zero) return point_in(g, {b, b, false});
  return point_in(g, {a, b, true});
}

bool triangle_meets_square(const SquareGeometry& g, Vec3 a, Vec3 b, Vec3 c) {
  const std::array<Vec3, 3> t{a, b, c};
  std::array<Sign, 3> s{};
  int pos = 0, neg = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    s[i] = compare(axis_coord(t[i], g.n), g.c);
    pos += s[i] == Sign::Positive;
    neg += s[i] == Sign::Negative;
  }
  if (pos == 3 || neg == 3) return false;
  if (pos == 0 && neg == 0) {
    // Coplanar: separating axes u, v and the triangle's side normals.
    const std::array<Vec2, 3> p{in_plane(g, a), in_plane(g, b), in_plane(g, c)};
    if (std::max({p[0].x, p[1].x, p[2].x}) < g.u0 || std::min({p[0].x, p[1].x, p[2].x}) > g.u1 ||
        std::max({p[0].y, p[1].y, p[2].y}) < g.v0 || std::min({p[0].y, p[1].y, p[2].y}) > g.v1)
      return false;
    const Sign turn = orient2d(p[0], p[1], p[2]);
    if (turn == Sign::Zero) {  // a degenerate triangle: its longest side covers it
      for (std::size_t i = 0; i < 3; ++i)
        if (segment_meets_rect(p[i], p[(i + 1) % 3], {g.u0, g.v0}, {g.u1, g.v1})) return true;
      return false;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      bool all_out = true;
      for (const Vec3& k : g.corners)
        if (orient2d(p[i], p[(i + 1) % 3], in_plane(g, k)) != -turn) all_out = false;
      if (all_out) return false;
    }
    return true;
  }
  // The section: vertices on the plane and crossings of sides.
  std::array<PlanePoint, 3> sec{};
  std::size_t m = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (s[i] == Sign::Zero) sec[m++] = {t[i], t[i], false};
    const std::size_t j = (i + 1) % 3;
    if (s[i] * s[j] == Sign::Negative) sec[m++] = {t[i], t[j], true};
  }
  if (m == 1) return point_in(g, sec[0]);
  // m == 2 (a plane meets a triangle not lying in it in a segment or a point).
  if (!overlaps(g, sec[0], sec[1], g.u, g.u0, g.u1) || !overlaps(g, sec[0], sec[1], g.v, g.v0, g.v1)) return false;
  int cp = 0, cn = 0;
  for (const Vec3& k : g.corners) {
    const Sign o = orient3d(a, b, c, k);
    cp += o == Sign::Positive;
    cn += o == Sign::Negative;
  }
  return cp < 4 && cn < 4;
}

}  // namespace pqmesh::tet3d
