// Rims and duplicate adjacency (cube_rims.hpp): trapezoidal sampling of a
// face rectangle by the traces of ∂P, samples located by components().
#include "mv3d/cube_rims.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <gmpxx.h>

#include "pqmesh/errors.hpp"

namespace pqmesh::mv3d {

namespace {


Vec3 make_point(int axis, double w, double u, double v) {
  std::array<double, 3> c{};
  c[static_cast<std::size_t>(axis)] = w;
  c[static_cast<std::size_t>((axis + 1) % 3)] = u;
  c[static_cast<std::size_t>((axis + 2) % 3)] = v;
  return {c[0], c[1], c[2]};
}

// The rectangle R = {axis = w} x [u0, u1] x [v0, v1], u on axis (axis+1)%3,
// v on axis (axis+2)%3.
struct Rect {
  int axis = 0;
  double w = 0, u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

struct P2 {
  mpq_class u, v;
};
struct Seg {
  P2 a, b;
};

// A double strictly between lo and hi, if any.
std::optional<double> pick(const mpq_class& lo, const mpq_class& hi) {
  const mpq_class m = (lo + hi) / 2;
  double x = m.get_d();
  if (lo < x && x < hi) return x;
  x = lo.get_d();
  while (!(lo < x)) x = std::nextafter(x, std::numeric_limits<double>::infinity());
  if (x < hi) return x;
  return std::nullopt;
}

struct Sampling {
  std::vector<Vec3> points;
  std::vector<int> in_plane;  // triangle lying in the plane containing the point, or -1
  int unresolved = 0;
};

// Trapezoidal samples of R minus the traces of `tris` (cube_rims.hpp).
Sampling sample_rect(const Domain3& dom, const std::vector<int>& tris, const Rect& r) {
  const int a = r.axis, ua = (a + 1) % 3, va = (a + 2) % 3;
  std::vector<Seg> segs;
  std::vector<std::pair<int, std::array<P2, 3>>> flat;  // triangles lying in the plane
  for (const int t : tris) {
    const auto& tri = dom.facet_triangles[static_cast<std::size_t>(t)];
    std::array<Vec3, 3> p;
    std::array<int, 3> s{};
    for (std::size_t i = 0; i < 3; ++i) {
      p[i] = dom.plc.vertices[static_cast<std::size_t>(tri[i])];
      const double h = axis_coord(p[i], a);
      s[i] = h > r.w ? 1 : (h < r.w ? -1 : 0);
    }
    const auto p2 = [&](std::size_t i) { return P2{mpq_class(axis_coord(p[i], ua)), mpq_class(axis_coord(p[i], va))}; };
    if (s[0] == 0 && s[1] == 0 && s[2] == 0) {
      const std::array<P2, 3> q{p2(0), p2(1), p2(2)};
      for (std::size_t i = 0; i < 3; ++i) segs.push_back({q[i], q[(i + 1) % 3]});
      flat.push_back({t, q});
      continue;
    }
    std::vector<P2> pts;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t j = (i + 1) % 3;
      if (s[i] == 0) pts.push_back(p2(i));
      if (s[i] * s[j] < 0) {
        // p_i + f (p_j - p_i) with f = (w - h_i) / (h_j - h_i), exact.
        const mpq_class hi(axis_coord(p[i], a)), hj(axis_coord(p[j], a));
        const mpq_class f = (mpq_class(r.w) - hi) / (hj - hi);
        const P2 pi = p2(i), pj = p2(j);
        pts.push_back({pi.u + f * (pj.u - pi.u), pi.v + f * (pj.v - pi.v)});
      }
    }
    if (pts.size() == 2) segs.push_back({pts[0], pts[1]});
    else if (pts.size() == 1) segs.push_back({pts[0], pts[0]});  // a vertex touching the plane: an event only
    else if (pts.size() > 2) throw InternalError("mv3d rims: a triangle meets a plane in more than two points");
  }
  const mpq_class U0(r.u0), U1(r.u1), V0(r.v0), V1(r.v1);
  std::vector<mpq_class> ev{U0, U1};
  for (const Seg& s : segs) {
    for (const P2* q : {&s.a, &s.b})
      if (q->u > U0 && q->u < U1) ev.push_back(q->u);
    // Where the trace crosses the sides v = v0, v = v1 of R: corners of the
    // regions of R, so slab boundaries too.
    for (const mpq_class* V : {&V0, &V1}) {
      if ((s.a.v < *V && s.b.v > *V) || (s.a.v > *V && s.b.v < *V)) {
        const mpq_class u = s.a.u + (*V - s.a.v) * (s.b.u - s.a.u) / (s.b.v - s.a.v);
        if (u > U0 && u < U1) ev.push_back(u);
      }
    }
  }
  std::sort(ev.begin(), ev.end());
  ev.erase(std::unique(ev.begin(), ev.end()), ev.end());
  Sampling out;
  for (std::size_t i = 0; i + 1 < ev.size(); ++i) {
    const std::optional<double> ud = pick(ev[i], ev[i + 1]);
    if (!ud) {
      ++out.unresolved;
      continue;
    }
    const mpq_class u(*ud);
    std::vector<mpq_class> vs{V0, V1};
    for (const Seg& s : segs) {
      const mpq_class& lo = s.a.u < s.b.u ? s.a.u : s.b.u;
      const mpq_class& hi = s.a.u < s.b.u ? s.b.u : s.a.u;
      if (!(lo < u && u < hi)) continue;
      const mpq_class v = s.a.v + (u - s.a.u) * (s.b.v - s.a.v) / (s.b.u - s.a.u);
      if (v > V0 && v < V1) vs.push_back(v);
    }
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    for (std::size_t j = 0; j + 1 < vs.size(); ++j) {
      const std::optional<double> vd = pick(vs[j], vs[j + 1]);
      if (!vd) {
        ++out.unresolved;
        continue;
      }
      const mpq_class v(*vd);
      int inside = -1;
      for (const auto& [t, q] : flat) {
        // Strictly inside (the point is on no side: sides are traces).
        int pos = 0, neg = 0;
        for (std::size_t k = 0; k < 3; ++k) {
          const P2& x = q[k];
          const P2& y = q[(k + 1) % 3];
          const int sg = sgn((y.u - x.u) * (v - x.v) - (y.v - x.v) * (u - x.u));
          pos += sg > 0;
          neg += sg < 0;
        }
        if (pos == 3 || neg == 3) {
          inside = t;
          break;
        }
      }
      out.points.push_back(make_point(a, r.w, *ud, *vd));
      out.in_plane.push_back(inside);
    }
  }
  return out;
}

int component_of_triangle(const CubeComponents& cc, int t) {
  const auto it = std::lower_bound(cc.triangle_component.begin(), cc.triangle_component.end(), std::pair{t, -1});
  if (it == cc.triangle_component.end() || it->first != t)
    throw InternalError("mv3d rims: a triangle lying in a face is not among the cube's triangles");
  return it->second;
}

// Component of each sample in the cube (-1: outside P).
std::vector<int> locate_samples(const Domain3& dom, const Cube& cube, const CubeHint* hint, const Sampling& s,
                                CubeComponents* comps) {
  std::vector<Vec3> marks;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (s.in_plane[i] < 0) marks.push_back(s.points[i]);
  CubeComponents cc = hint ? components(dom, cube, *hint, true, marks) : components(dom, cube, true, marks);
  std::vector<int> out;
  std::size_t m = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    out.push_back(s.in_plane[i] >= 0 ? component_of_triangle(cc, s.in_plane[i]) : cc.mark_component[m++]);
  if (comps) *comps = std::move(cc);
  return out;
}

std::vector<int> triangles_of(const CubeComponents& cc) {
  std::vector<int> t;
  for (const auto& [tri, k] : cc.triangle_component) t.push_back(tri);
  return t;
}

}  // namespace

std::vector<int> CubeRims::face_mask() const {
  std::vector<int> mask(comps.components.size(), 0);
  for (std::size_t f = 0; f < 6; ++f)
    for (const RimSample& s : faces[f]) mask[static_cast<std::size_t>(s.component)] |= 1 << f;
  return mask;
}

CubeRims cube_rims(const Domain3& domain, const Cube& cube) {
  const CubeComponents base = components(domain, cube);
  const std::vector<int> tris = triangles_of(base);
  Sampling all;
  std::vector<int> face_of;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
      const Rect r{axis, side == 0 ? axis_coord(cube.lo, axis) : axis_coord(cube.hi, axis), axis_coord(cube.lo, ua), axis_coord(cube.hi, ua),
                   axis_coord(cube.lo, va), axis_coord(cube.hi, va)};
      const Sampling s = sample_rect(domain, tris, r);
      all.points.insert(all.points.end(), s.points.begin(), s.points.end());
      all.in_plane.insert(all.in_plane.end(), s.in_plane.begin(), s.in_plane.end());
      all.unresolved += s.unresolved;
      face_of.insert(face_of.end(), s.points.size(), axis * 2 + side);
    }
  CubeRims out;
  const std::vector<int> comp = locate_samples(domain, cube, nullptr, all, &out.comps);
  out.unresolved = all.unresolved;
  for (std::size_t i = 0; i < comp.size(); ++i)
    if (comp[i] >= 0) out.faces[static_cast<std::size_t>(face_of[i])].push_back({all.points[i], all.in_plane[i], comp[i]});
  return out;
}

DuplicateAdjacency adjacent_duplicates(const Domain3& domain, const Cube& big, const Cube& small) {
  return adjacent_duplicates(domain, big, nullptr, small, nullptr);
}

DuplicateAdjacency adjacent_duplicates(const Domain3& domain, const Cube& big, const CubeHint& big_hint, const Cube& small,
                                       const CubeHint& small_hint) {
  return adjacent_duplicates(domain, big, &big_hint, small, &small_hint);
}

DuplicateAdjacency adjacent_duplicates(const Domain3& domain, const Cube& big, const CubeHint* big_hint, const Cube& small,
                                       const CubeHint* small_hint) {
  DuplicateAdjacency out;
  for (int a = 0; a < 3 && out.axis < 0; ++a) {
    const int ua = (a + 1) % 3, va = (a + 2) % 3;
    const bool inside = axis_coord(big.lo, ua) <= axis_coord(small.lo, ua) && axis_coord(small.hi, ua) <= axis_coord(big.hi, ua) &&
                        axis_coord(big.lo, va) <= axis_coord(small.lo, va) && axis_coord(small.hi, va) <= axis_coord(big.hi, va);
    if (!inside) continue;
    if (axis_coord(small.lo, a) == axis_coord(big.hi, a)) out.value = axis_coord(small.lo, a);
    else if (axis_coord(small.hi, a) == axis_coord(big.lo, a)) out.value = axis_coord(small.hi, a);
    else continue;
    out.axis = a;
  }
  if (out.axis < 0) throw std::invalid_argument("adjacent_duplicates: small's face must lie in a face of big");
  const int a = out.axis, ua = (a + 1) % 3, va = (a + 2) % 3;
  const Rect r{a, out.value, axis_coord(small.lo, ua), axis_coord(small.hi, ua), axis_coord(small.lo, va), axis_coord(small.hi, va)};
  // Every triangle with a trace crossing the open rectangle meets both closed cubes.
  const std::vector<int> tris =
      small_hint ? triangles_meeting(domain, small, small_hint->candidates)
                 : triangles_meeting(domain, small);
  const Sampling s = sample_rect(domain, tris, r);
  out.unresolved = s.unresolved;
  const std::vector<int> kb = locate_samples(domain, big, big_hint, s, nullptr),
                         ks = locate_samples(domain, small, small_hint, s, nullptr);
  for (std::size_t i = 0; i < kb.size(); ++i) {
    if ((kb[i] < 0) != (ks[i] < 0)) throw InternalError("mv3d rims: the two cubes disagree on a face point");
    if (kb[i] < 0) continue;
    out.pairs.push_back({kb[i], ks[i]});
    out.samples_big.push_back({s.points[i], s.in_plane[i], kb[i]});
    out.samples_small.push_back({s.points[i], s.in_plane[i], ks[i]});
  }
  std::sort(out.pairs.begin(), out.pairs.end());
  out.pairs.erase(std::unique(out.pairs.begin(), out.pairs.end()), out.pairs.end());
  return out;
}

}  // namespace pqmesh::mv3d
