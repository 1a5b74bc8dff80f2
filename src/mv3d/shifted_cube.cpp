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
    if (axis_coord(p, k) < lo_of(c, k) || axis_coord(p, k) > hi_of(c, k)) return false;
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

Line make_line(int d, Pos f1, Pos f2) {
  Line l{d, std::move(f1), std::move(f2), {}, {}};
  l.lo = {l.f1.lo, l.f2.lo};
  l.hi = {l.f1.hi, l.f2.hi};
  return l;
}

Pos Pos::of_pert(Pert v) {
  Pos p;
  bracket_one(v.c[0], p.lo, p.hi);
  p.given = true;
  p.exact = std::make_shared<const Pert>(std::move(v));
  return p;
}

namespace {

// The exact crossing of line l with the plane of triangle abc (not parallel).
Pert crossing(const Line& l, Vec3 a, Vec3 b, Vec3 c) {
  const int o1 = (l.d + 1) % 3, o2 = (l.d + 2) % 3;
  const mpq_class bx = q(b.x) - q(a.x), by = q(b.y) - q(a.y), bz = q(b.z) - q(a.z);
  const mpq_class cx = q(c.x) - q(a.x), cy = q(c.y) - q(a.y), cz = q(c.z) - q(a.z);
  const std::array<mpq_class, 3> n{by * cz - bz * cy, bz * cx - bx * cz, bx * cy - by * cx};
  // n . (p - a) = 0  =>  p_d = a_d - (n_o1 (f1 - a_o1) + n_o2 (f2 - a_o2)) / n_d
  const mpq_class inv = mpq_class(-1) / n[static_cast<std::size_t>(l.d)];
  const mpq_class m1 = n[static_cast<std::size_t>(o1)] * inv, m2 = n[static_cast<std::size_t>(o2)] * inv;
  const Pert& f1 = l.f1.value();
  const Pert& f2 = l.f2.value();
  // Coefficient by coefficient (no Pert temporaries).
  Pert pos;
  pos.c[0] = (f1.c[0] - q(axis_coord(a, o1))) * m1 + (f2.c[0] - q(axis_coord(a, o2))) * m2 + q(axis_coord(a, l.d));
  for (std::size_t k = 1; k < pos.c.size(); ++k) {
    if (sgn(f1.c[k]) != 0) pos.c[k] += f1.c[k] * m1;
    if (sgn(f2.c[k]) != 0) pos.c[k] += f2.c[k] * m2;
  }
  return pos;
}

int sign_of_int(int v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// sign(x - y) for a plane-kind x (x0 + sx e^tx) and a y of another kind, the brackets
// overlapping (y.lo <= x0 <= y.hi): coefficient by coefficient, GMP only for
// a constant part of y that is not a double.
int compare_plane(const Pos& x, const Pos& y) {
  int r = 0;
  if (y.lo == y.hi) r = x.lo < y.lo ? -1 : (x.lo > y.lo ? 1 : 0);  // c0(y) == y.lo exactly
  else r = -sign_of_int(cmp(y.value().c[0], x.lo));
  if (r != 0) return r;
  for (int k = 1; k < 6; ++k) {
    const int xk = x.term == k ? x.sgn : 0;
    const mpq_class& yk = y.value().c[static_cast<std::size_t>(k)];
    const int s = xk == 0 ? -sgn(yk) : -mpq_cmp_si(yk.get_mpq_t(), xk, 1);
    if (s != 0) return s > 0 ? 1 : -1;
  }
  return 0;
}

}  // namespace

const Pert& Pos::value() const {
  if (!exact) {
    if (line) exact = std::make_shared<const Pert>(crossing(*line, a, b, c));
    else exact = std::make_shared<const Pert>(term >= 0 ? Pert::shifted(lo, term, sgn) : Pert::constant(lo));
  }
  return *exact;
}

int Pos::coefficient_sign(int k) const {
  if (plane_kind()) return term == k ? sgn : 0;
  return sign_of_int(mpq_sgn(value().c[static_cast<std::size_t>(k)].get_mpq_t()));
}

int compare(const Pos& x, const Pos& y) {
  if (x.hi < y.lo) return -1;
  if (x.lo > y.hi) return 1;
  if (x.plane_kind() && !y.plane_kind()) return compare_plane(x, y);
  if (y.plane_kind() && !x.plane_kind()) return -compare_plane(y, x);
  if (x.plane_kind() && y.plane_kind()) {
    // x - y = (x0 - y0) + sx e^tx - sy e^ty
    if (x.lo != y.lo) return x.lo < y.lo ? -1 : 1;
    std::array<int, 6> d{};
    if (x.term >= 0) d[static_cast<std::size_t>(x.term)] += x.sgn;
    if (y.term >= 0) d[static_cast<std::size_t>(y.term)] -= y.sgn;
    for (const int v : d)
      if (v != 0) return v > 0 ? 1 : -1;
    return 0;
  }
  return detail::compare(x.value(), y.value());
}

Pos plane_pos(const Cube& c, int axis, int side) {
  return side == 0 ? Pos::of_double(lo_of(c, axis), detail::kE1 + axis, -1)
                   : Pos::of_double(hi_of(c, axis), detail::kE1 + axis, 1);
}

// Does the line cross the closed triangle abc (oriented outward)? The line is
// generic (file comment), so it crosses the plane in one point (or is
// parallel to it) and the point is strictly inside or strictly outside the
// triangle. pos: coordinate along d; entering: moving in +d enters P.
bool line_hit(const Line& l, Vec3 a, Vec3 b, Vec3 c, Pos& pos, bool& entering) {
  const int o1 = (l.d + 1) % 3, o2 = (l.d + 2) % 3;
  // Filter: a fixed coordinate whose constant part lies strictly outside the
  // triangle's range misses it whatever the infinitesimals.
  const double mn1 = std::min({axis_coord(a, o1), axis_coord(b, o1), axis_coord(c, o1)}), mx1 = std::max({axis_coord(a, o1), axis_coord(b, o1), axis_coord(c, o1)});
  const double mn2 = std::min({axis_coord(a, o2), axis_coord(b, o2), axis_coord(c, o2)}), mx2 = std::max({axis_coord(a, o2), axis_coord(b, o2), axis_coord(c, o2)});
  if (l.hi[0] < mn1 || l.lo[0] > mx1 || l.hi[1] < mn2 || l.lo[1] > mx2) return false;  // brackets: exact
  // Brackets straddling a bound (non-double constant parts): decide exactly.
  if ((l.lo[0] < mn1 && cmp(l.f1.value().c[0], mn1) < 0) || (l.hi[0] > mx1 && cmp(l.f1.value().c[0], mx1) > 0) ||
      (l.lo[1] < mn2 && cmp(l.f2.value().c[0], mn2) < 0) || (l.hi[1] > mx2 && cmp(l.f2.value().c[0], mx2) > 0))
    return false;
  // sign of the normal's d component: orient2d of the projection dropping d,
  // whose axes are (o1, o2) in this cyclic order (predicates.hpp).
  const int nd = static_cast<int>(orient2d_projected(a, b, c, l.d));
  if (nd == 0) return false;  // line parallel to the plane, and not in it
  const bool point_line = l.lo[0] == l.hi[0] && l.lo[1] == l.hi[1];  // exact double fixed coordinates
  const std::array<Vec3, 3> t{a, b, c};
  for (int i = 0; i < 3; ++i) {
    const Vec3 u = t[static_cast<std::size_t>(i)], v = t[static_cast<std::size_t>((i + 1) % 3)];
    // Exact filter: orient2d(u, v, .) is affine, so if it has one non-zero
    // sign at the four corners of the box bracketing P's constant part, that
    // is its sign at P whatever the infinitesimals.
    const Vec2 u2{axis_coord(u, o1), axis_coord(u, o2)}, v2{axis_coord(v, o1), axis_coord(v, o2)};
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
    // orient2d(u, v, P) = (v1 - u1)(P2 - u2) - (v2 - u2)(P1 - u1), affine in P:
    // its sign is that of the first non-zero coefficient. Constant part: at
    // a point line it is orient2d at the point, i.e. corner_sign = 0.
    // Coefficient k >= 1: f2_k b1 - f1_k b2; when one of f1_k, f2_k is zero
    // its sign is a product of signs (b1, b2 are differences of doubles,
    // whose signs are comparisons), so GMP runs only when both are non-zero
    // or the constant part is not a double.
    int sg = 0;
    if (!point_line) {
      const Pert& f1 = l.f1.value();
      const Pert& f2 = l.f2.value();
      const mpq_class b1 = q(axis_coord(v, o1)) - q(axis_coord(u, o1));
      const mpq_class b2 = q(axis_coord(v, o2)) - q(axis_coord(u, o2));
      sg = sign_of_int(sgn((f2.c[0] - q(axis_coord(u, o2))) * b1 - (f1.c[0] - q(axis_coord(u, o1))) * b2));
    }
    const int sb1 = axis_coord(v, o1) > axis_coord(u, o1) ? 1 : (axis_coord(v, o1) < axis_coord(u, o1) ? -1 : 0);
    const int sb2 = axis_coord(v, o2) > axis_coord(u, o2) ? 1 : (axis_coord(v, o2) < axis_coord(u, o2) ? -1 : 0);
    for (int k = 1; k < 6 && sg == 0; ++k) {
      const int s1 = l.f1.coefficient_sign(k), s2 = l.f2.coefficient_sign(k);
      if (s1 == 0) sg = s2 * sb1;
      else if (s2 == 0) sg = -s1 * sb2;
      else {
        const mpq_class b1 = q(axis_coord(v, o1)) - q(axis_coord(u, o1));
        const mpq_class b2 = q(axis_coord(v, o2)) - q(axis_coord(u, o2));
        const auto kk = static_cast<std::size_t>(k);
        sg = sign_of_int(sgn(l.f2.value().c[kk] * b1 - l.f1.value().c[kk] * b2));
      }
    }
    if (sg == 0) throw InternalError("mv3d: a probe line passes through a triangle side");
    if (sg != nd) return false;
  }
  entering = nd < 0;
  pos = Pos{};
  pos.line = &l;
  pos.a = a;
  pos.b = b;
  pos.c = c;
  // Bracket of the constant part p0 of the crossing: a double estimate
  // +- delta, each end checked exactly. With X = (t, f1, f2) in axes
  // (d, o1, o2), n . (X - a) = n_d (t - p0), and n . (X - a) has the sign of
  // orient3d(a, b, c, X); it is affine in (f1, f2), so one sign at the four
  // corners of their brackets holds for their constant parts.
  const auto point = [&](double td, double t1, double t2) {
    Vec3 x{};
    (l.d == 0 ? x.x : l.d == 1 ? x.y : x.z) = td;
    (o1 == 0 ? x.x : o1 == 1 ? x.y : x.z) = t1;
    (o2 == 0 ? x.x : o2 == 1 ? x.y : x.z) = t2;
    return x;
  };
  const auto below_or_above = [&](double td) {  // sign(td - p0) if one on the bracket box, else 0
    int s = 0;
    for (int k = 0; k < (point_line ? 1 : 4); ++k) {
      const double t1 = (k & 1) ? l.hi[0] : l.lo[0], t2 = (k & 2) ? l.hi[1] : l.lo[1];
      const int g = static_cast<int>(orient3d(a, b, c, point(td, t1, t2))) * nd;
      if (g == 0 || (s != 0 && g != s)) return 0;
      s = g;
    }
    return s;
  };
  const Vec3 ab = b - a, ac = c - a;
  const double n[3] = {ab.y * ac.z - ab.z * ac.y, ab.z * ac.x - ab.x * ac.z, ab.x * ac.y - ab.y * ac.x};
  const double f1 = 0.5 * (l.lo[0] + l.hi[0]), f2 = 0.5 * (l.lo[1] + l.hi[1]);
  const double nd_d = n[l.d];
  pos.lo = -HUGE_VAL;
  pos.hi = HUGE_VAL;
  if (axis_coord(a, l.d) == axis_coord(b, l.d) && axis_coord(a, l.d) == axis_coord(c, l.d)) {
    // The plane x_d = a_d: n_o1 = n_o2 = 0 exactly, so the crossing is the
    // constant a_d with every infinitesimal coefficient 0 (crossing() would
    // give m1 = m2 = 0): a plane-kind Pos, compared without GMP.
    pos = Pos::of_double(axis_coord(a, l.d));
  } else if (nd_d != 0) {
    const double est = axis_coord(a, l.d) - (n[o1] * (f1 - axis_coord(a, o1)) + n[o2] * (f2 - axis_coord(a, o2))) / nd_d;
    double scale = std::fabs(est) + std::fabs(f1) + std::fabs(f2);
    for (const Vec3 p : {a, b, c}) scale += std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z);
    const double delta = std::max(1e-9 * scale, 1e-300);
    if (std::isfinite(est) && std::isfinite(delta) && below_or_above(est - delta) < 0 && below_or_above(est + delta) > 0) {
      pos.lo = est - delta;
      pos.hi = est + delta;
    }
  }
  return true;
}

// Does segment uv cross the face of C_e on plane (axis, side) inside the
// face? Then w receives coordinate (axis + 2) % 3 of the crossing point.
bool segment_crosses_face(Vec3 u, Vec3 v, const Cube& c, int axis, int side, Pert* w) {
  // Straddle, exactly on doubles: u_axis > hi_axis + e  <=>  u_axis > hi_axis, and
  // u_axis < lo_axis - e  <=>  u_axis < lo_axis.
  const auto beyond = [&](Vec3 p) {
    return side == 1 ? axis_coord(p, axis) > hi_of(c, axis) : axis_coord(p, axis) < lo_of(c, axis);
  };
  if (beyond(u) == beyond(v)) return false;
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    if ((axis_coord(u, j) < lo_of(c, j) && axis_coord(v, j) < lo_of(c, j)) || (axis_coord(u, j) > hi_of(c, j) && axis_coord(v, j) > hi_of(c, j)))
      return false;
  }
  // The crossing x = u + t (v - u) with the shifted plane x_axis = A + s e^(axis+1)
  // (A the face plane, s = +1 on side 1, -1 on side 0): coordinate j is
  // x0_j + s r_j e^(axis+1), r_j = (v_j - u_j) / (v_a - u_a), x0_j its
  // constant part at x_axis = A. It is inside the face iff, for both
  // j != axis, lo_j - e^(j+1) < x_j < hi_j + e^(j+1) (never equal: the
  // e^(j+1) coefficient of the difference is +-1).
  const double plane_a = side == 1 ? hi_of(c, axis) : lo_of(c, axis);
  const int sa = axis_coord(v, axis) > axis_coord(u, axis) ? 1 : -1;  // the straddle makes them differ
  const int s_face = side == 1 ? 1 : -1;
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    // Constant parts: (x0 - L)(v_a - u_a) = -orient2d((u_a, u_j), (v_a, v_j), (A, L)).
    const Vec2 u2{axis_coord(u, axis), axis_coord(u, j)}, v2{axis_coord(v, axis), axis_coord(v, j)};
    int sl = -static_cast<int>(orient2d(u2, v2, {plane_a, lo_of(c, j)})) * sa;  // sign(x0_j - lo_j)
    int sh = -static_cast<int>(orient2d(u2, v2, {plane_a, hi_of(c, j)})) * sa;  // sign(x0_j - hi_j)
    if (sl == 0 || sh == 0) {
      // x0_j on a plane of C: the first non-zero infinitesimal coefficient of
      // x_j - (lo_j - e^(j+1)) (resp. - (hi_j + e^(j+1))) decides: s r_j on
      // e^(axis+1), +1 (resp. -1) on e^(j+1); e^(axis+1) comes first iff
      // axis < j. sign(r_j) = sign(v_j - u_j) sign(v_a - u_a), by comparisons.
      const int sr = (axis_coord(v, j) > axis_coord(u, j) ? 1 : (axis_coord(v, j) < axis_coord(u, j) ? -1 : 0)) * sa;
      const auto tie = [&](int lower_plane) { return axis < j && sr != 0 ? s_face * sr : (lower_plane ? 1 : -1); };
      if (sl == 0) sl = tie(1);
      if (sh == 0) sh = tie(0);
    }
    if (sl < 0 || sh > 0) return false;
  }
  if (w) {
    // Coordinate j = (axis + 2) % 3 of the crossing, exactly: constant part
    // u_j + (A - u_a) r_j, coefficient s r_j on e^(axis+1).
    const int j = (axis + 2) % 3;
    const mpq_class den = q(axis_coord(v, axis)) - q(axis_coord(u, axis)), off = q(plane_a) - q(axis_coord(u, axis));
    const mpq_class r = (q(axis_coord(v, j)) - q(axis_coord(u, j))) / den;
    for (mpq_class& y : w->c) y = 0;  // reuses the caller's storage (no Pert temporary)
    w->c[0] = q(axis_coord(u, j)) + off * r;
    w->c[static_cast<std::size_t>(detail::kE1 + axis)] = side == 1 ? mpq_class(r) : mpq_class(-r);
  }
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
  return make_line(d, plane_pos(c, (d + 1) % 3, s1), plane_pos(c, (d + 2) % 3, s2));
}

// Corner id: bit k = side on axis k. The start (side 0 along d) or end of edge e.
int edge_corner(int e, int end) {
  const int d = e / 4, s1 = (e / 2) % 2, s2 = e % 2;
  return (end << d) | (s1 << ((d + 1) % 3)) | (s2 << ((d + 2) % 3));
}

bool triangle_meets(const Domain3& dom, int t, const Cube& c, EdgeLines& edge_lines) {
  const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
  const Vec3 a = dom.plc.vertices[static_cast<std::size_t>(tri[0])];
  const Vec3 b = dom.plc.vertices[static_cast<std::size_t>(tri[1])];
  const Vec3 p = dom.plc.vertices[static_cast<std::size_t>(tri[2])];
  for (int k = 0; k < 3; ++k) {
    if (std::max({axis_coord(a, k), axis_coord(b, k), axis_coord(p, k)}) < lo_of(c, k)) return false;
    if (std::min({axis_coord(a, k), axis_coord(b, k), axis_coord(p, k)}) > hi_of(c, k)) return false;
  }
  if (vertex_inside(a, c) || vertex_inside(b, c) || vertex_inside(p, c)) return true;
  const std::array<Vec3, 3> v{a, b, p};
  for (int i = 0; i < 3; ++i)
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
        if (segment_crosses_face(v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>((i + 1) % 3)], c, axis, side,
                                 nullptr))
          return true;
  for (const Line& l : edge_lines.get()) {
    Pos pos;
    bool entering = false;
    if (!line_hit(l, a, b, p, pos, entering)) continue;
    if (compare(pos, plane_pos(c, l.d, 0)) > 0 && compare(pos, plane_pos(c, l.d, 1)) < 0) return true;
  }
  return false;
}

PPoint corner_point(const Cube& c, int k) {
  return {plane_pos(c, 0, k & 1), plane_pos(c, 1, (k >> 1) & 1), plane_pos(c, 2, (k >> 2) & 1)};
}

bool walk_status(const Domain3& dom, std::span<const int> tris, const PPoint& from, bool from_in, const PPoint& to) {
  bool in = from_in;
  PPoint cur = from;
  for (int d = 0; d < 3; ++d) {
    const auto du = static_cast<std::size_t>(d);
    if (compare(cur[du], to[du]) == 0) continue;
    const Line l = make_line(d, cur[static_cast<std::size_t>((d + 1) % 3)], cur[static_cast<std::size_t>((d + 2) % 3)]);
    Pos s = cur[du], t = to[du];
    if (compare(s, t) > 0) std::swap(s, t);
    for (const int ti : tris) {
      const auto& tri = dom.facet_triangles[static_cast<std::size_t>(ti)];
      Pos pos;
      bool entering = false;
      if (!line_hit(l, dom.plc.vertices[static_cast<std::size_t>(tri[0])], dom.plc.vertices[static_cast<std::size_t>(tri[1])],
                    dom.plc.vertices[static_cast<std::size_t>(tri[2])], pos, entering))
        continue;
      const int r1 = compare(pos, s), r2 = compare(pos, t);
      if (r1 == 0 || r2 == 0) throw InternalError("mv3d: a status walk passes through the boundary of P at a path vertex");
      if (r1 > 0 && r2 < 0) in = !in;
    }
    cur[du] = to[du];
  }
  return in;
}

}  // namespace pqmesh::mv3d::detail
