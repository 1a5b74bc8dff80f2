// Exact geometry against the shifted box C_e (shifted_cube.hpp). The
// genericity facts these functions rely on are argued in cube_components.cpp.
#include "mv3d/shifted_cube.hpp"

#include <algorithm>
#include <cmath>

#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::mv3d::detail {
namespace {
mpq_class q(double v) { return mpq_class(v); }
}  // namespace

// The shifted plane of C_e: axis k at lo_k - e^(k+1) (side 0) or hi_k + e^(k+1) (side 1).
Pert plane(const Cube& c, int axis, int side) {
  return side == 0 ? Pert::shifted(lo_of(c, axis), detail::kE1 + axis, -1)
                   : Pert::shifted(hi_of(c, axis), detail::kE1 + axis, 1);
}

// In C_e  <=>  in the closed box C (the shift is outward).
bool vertex_inside(Vec3 p, const Cube& c) {
  for (int k = 0; k < 3; ++k)
    if (at(p, k) < lo_of(c, k) || at(p, k) > hi_of(c, k)) return false;
  return true;
}

int side_sign(double v, const Pert& a) { return (Pert::constant(v) - a).sign(); }

namespace {

void bracket_one(const mpq_class& c0, double& lo, double& hi) {
  const double d = c0.get_d();
  if (cmp(c0, d) == 0) {
    lo = hi = d;
    return;
  }
  // get_d truncates: |c0 - d| < ulp(d), so the neighbours bracket c0.
  lo = std::nextafter(d, -HUGE_VAL);
  hi = std::nextafter(d, HUGE_VAL);
}

}  // namespace

Line make_line(int d, Pert f1, Pert f2) {
  Line l{d, std::move(f1), std::move(f2), {}, {}};
  bracket_one(l.f1.c[0], l.lo[0], l.hi[0]);
  bracket_one(l.f2.c[0], l.lo[1], l.hi[1]);
  return l;
}

// Does the line cross the closed triangle abc (oriented outward)? The line is
// generic (file comment), so it crosses the plane in one point (or is
// parallel to it) and the point is strictly inside or strictly outside the
// triangle. pos: coordinate along d; entering: moving in +d enters P.
bool line_hit(const Line& l, Vec3 a, Vec3 b, Vec3 c, Pert& pos, bool& entering) {
  const int o1 = (l.d + 1) % 3, o2 = (l.d + 2) % 3;
  // Filter: a fixed coordinate whose constant part lies strictly outside the
  // triangle's range misses it whatever the infinitesimals.
  const double mn1 = std::min({at(a, o1), at(b, o1), at(c, o1)}), mx1 = std::max({at(a, o1), at(b, o1), at(c, o1)});
  const double mn2 = std::min({at(a, o2), at(b, o2), at(c, o2)}), mx2 = std::max({at(a, o2), at(b, o2), at(c, o2)});
  if (l.hi[0] < mn1 || l.lo[0] > mx1 || l.hi[1] < mn2 || l.lo[1] > mx2) return false;  // brackets: exact
  if (cmp(l.f1.c[0], mn1) < 0 || cmp(l.f1.c[0], mx1) > 0 || cmp(l.f2.c[0], mn2) < 0 || cmp(l.f2.c[0], mx2) > 0)
    return false;
  // sign of the normal's d component: orient2d of the projection dropping d,
  // whose axes are (o1, o2) in this cyclic order (predicates.hpp).
  const int nd = static_cast<int>(orient2d_projected(a, b, c, l.d));
  if (nd == 0) return false;  // line parallel to the plane, and not in it
  const std::array<Vec3, 3> t{a, b, c};
  for (int i = 0; i < 3; ++i) {
    const Vec3 u = t[static_cast<std::size_t>(i)], v = t[static_cast<std::size_t>((i + 1) % 3)];
    // Exact filter: orient2d(u, v, .) is affine, so if it has one non-zero
    // sign at the four corners of the box bracketing P's constant part, that
    // is its sign at P whatever the infinitesimals.
    const Vec2 u2{at(u, o1), at(u, o2)}, v2{at(v, o1), at(v, o2)};
    int corner_sign = static_cast<int>(orient2d(u2, v2, {l.lo[0], l.lo[1]}));
    if (corner_sign != 0) {
      for (const Vec2 p : {Vec2{l.hi[0], l.lo[1]}, Vec2{l.lo[0], l.hi[1]}, Vec2{l.hi[0], l.hi[1]}})
        if (static_cast<int>(orient2d(u2, v2, p)) != corner_sign) {
          corner_sign = 0;
          break;
        }
    }
    if (corner_sign != 0) {
      if (corner_sign != nd) return false;
      continue;
    }
    // orient2d(u, v, P) = (v1 - u1)(P2 - u2) - (v2 - u2)(P1 - u1), affine in P.
    const Pert s = (l.f2 - Pert::constant(at(u, o2))) * (q(at(v, o1)) - q(at(u, o1))) -
                   (l.f1 - Pert::constant(at(u, o1))) * (q(at(v, o2)) - q(at(u, o2)));
    const int sg = s.sign();
    if (sg == 0) throw InternalError("mv3d: a probe line passes through a triangle side");
    if (sg != nd) return false;
  }
  const mpq_class bx = q(b.x) - q(a.x), by = q(b.y) - q(a.y), bz = q(b.z) - q(a.z);
  const mpq_class cx = q(c.x) - q(a.x), cy = q(c.y) - q(a.y), cz = q(c.z) - q(a.z);
  const std::array<mpq_class, 3> n{by * cz - bz * cy, bz * cx - bx * cz, bx * cy - by * cx};
  // n . (p - a) = 0  =>  p_d = a_d - (n_o1 (f1 - a_o1) + n_o2 (f2 - a_o2)) / n_d
  const mpq_class inv = mpq_class(-1) / n[static_cast<std::size_t>(l.d)];
  pos = (l.f1 - Pert::constant(at(a, o1))) * (n[static_cast<std::size_t>(o1)] * inv) +
        (l.f2 - Pert::constant(at(a, o2))) * (n[static_cast<std::size_t>(o2)] * inv);
  pos.c[0] += q(at(a, l.d));
  entering = nd < 0;
  return true;
}

// Does segment uv cross the face of C_e on plane (axis, side) inside the
// face? Then w receives the crossing point (all three coordinates).
bool segment_crosses_face(Vec3 u, Vec3 v, const Cube& c, int axis, int side, std::array<Pert, 3>* w) {
  // Straddle, exactly on doubles: u_axis > hi_axis + e  <=>  u_axis > hi_axis, and
  // u_axis < lo_axis - e  <=>  u_axis < lo_axis.
  const auto beyond = [&](Vec3 p) {
    return side == 1 ? at(p, axis) > hi_of(c, axis) : at(p, axis) < lo_of(c, axis);
  };
  if (beyond(u) == beyond(v)) return false;
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    if ((at(u, j) < lo_of(c, j) && at(v, j) < lo_of(c, j)) || (at(u, j) > hi_of(c, j) && at(v, j) > hi_of(c, j)))
      return false;
  }
  const Pert a = plane(c, axis, side);
  std::array<Pert, 3> p;
  const Pert off = a - Pert::constant(at(u, axis));
  const mpq_class den = q(at(v, axis)) - q(at(u, axis));
  for (int j = 0; j < 3; ++j) {
    if (j == axis) {
      p[static_cast<std::size_t>(j)] = a;
      continue;
    }
    Pert x = off * ((q(at(v, j)) - q(at(u, j))) / den);
    x.c[0] += q(at(u, j));
    const int sl = detail::compare(x, plane(c, j, 0)), sh = detail::compare(x, plane(c, j, 1));
    if (sl == 0 || sh == 0) throw InternalError("mv3d: a segment passes through an edge of the shifted cube");
    if (sl < 0 || sh > 0) return false;
    p[static_cast<std::size_t>(j)] = std::move(x);
  }
  if (w) *w = std::move(p);
  return true;
}

bool segment_meets(Vec3 u, Vec3 v, const Cube& c) {
  if (vertex_inside(u, c) || vertex_inside(v, c)) return true;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      if (segment_crosses_face(u, v, c, axis, side, nullptr)) return true;
  return false;
}

// Cube edge index d * 4 + s1 * 2 + s2: direction d, side s1 on axis (d+1)%3,
// s2 on axis (d+2)%3.
Line cube_edge_line(const Cube& c, int e) {
  const int d = e / 4, s1 = (e / 2) % 2, s2 = e % 2;
  return make_line(d, plane(c, (d + 1) % 3, s1), plane(c, (d + 2) % 3, s2));
}

// Corner id: bit k = side on axis k. The start (side 0 along d) or end of edge e.
int edge_corner(int e, int end) {
  const int d = e / 4, s1 = (e / 2) % 2, s2 = e % 2;
  return (end << d) | (s1 << ((d + 1) % 3)) | (s2 << ((d + 2) % 3));
}

bool triangle_meets(const Domain3& dom, int t, const Cube& c, const std::array<Line, 12>& edge_lines) {
  const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
  const Vec3 a = dom.plc.vertices[static_cast<std::size_t>(tri[0])];
  const Vec3 b = dom.plc.vertices[static_cast<std::size_t>(tri[1])];
  const Vec3 p = dom.plc.vertices[static_cast<std::size_t>(tri[2])];
  for (int k = 0; k < 3; ++k) {
    if (std::max({at(a, k), at(b, k), at(p, k)}) < lo_of(c, k)) return false;
    if (std::min({at(a, k), at(b, k), at(p, k)}) > hi_of(c, k)) return false;
  }
  if (vertex_inside(a, c) || vertex_inside(b, c) || vertex_inside(p, c)) return true;
  const std::array<Vec3, 3> v{a, b, p};
  for (int i = 0; i < 3; ++i)
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
        if (segment_crosses_face(v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>((i + 1) % 3)], c, axis, side,
                                 nullptr))
          return true;
  for (const Line& l : edge_lines) {
    Pert pos;
    bool entering = false;
    if (!line_hit(l, a, b, p, pos, entering)) continue;
    if (detail::compare(pos, plane(c, l.d, 0)) > 0 && detail::compare(pos, plane(c, l.d, 1)) < 0) return true;
  }
  return false;
}

}  // namespace pqmesh::mv3d::detail
