#pragma once
// PLC fixtures for the domain tests, built in code. Every facet here is listed
// counter-clockwise seen from outside the solid it bounds (right-hand normal
// outward), so tests can compare make_domain's orientation with it.
#include <array>
#include <algorithm>
#include <cmath>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/plc.hpp"

namespace pqmesh::test {

// Axis-aligned box [lo, hi]; vertex i = (bit0 ? hi.x : lo.x, bit1 ? ..y, bit2 ? ..z) + offset.
// Facets: 0 bottom (-z), 1 top (+z), 2 front (-y), 3 back (+y), 4 left (-x), 5 right (+x).
inline void add_box(Plc3& plc, Vec3 lo, Vec3 hi) {
  const int o = static_cast<int>(plc.vertices.size());
  for (int i = 0; i < 8; ++i)
    plc.vertices.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) plc.facets.push_back(Facet3{{{o + q[0], o + q[1], o + q[2], o + q[3]}}, 0});
}

inline Plc3 box(Vec3 lo = {0, 0, 0}, Vec3 hi = {1, 1, 1}) {
  Plc3 plc;
  add_box(plc, lo, hi);
  return plc;
}

// The unit cube with its bottom split along the diagonal (0, 2) into two
// triangles: facets 0 = (0, 3, 2) and 1 = (0, 2, 1), then top, front, right,
// back, left. Facet k has marker k, so make_domain keeps the coplanar halves
// apart and the edge (0, 2) between them is flat (unsupported input).
inline Plc3 cube_with_split_bottom() {
  Plc3 plc;
  plc.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<std::vector<int>> loops = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                               {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (std::size_t k = 0; k < loops.size(); ++k) plc.facets.push_back(Facet3{{loops[k]}, static_cast<int>(k)});
  return plc;
}

// The L-shaped prism over (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), z in [0, 1].
// Its vertical edge over (1,1) is reflex. The side x = 1 (between (1,1) and
// (1,2)) is split by the diagonal from (1,1,1) to (1,2,0) into two triangles
// with their own markers. Vertex k lies over polygon vertex k at z = 0, 6 + k
// at z = 1. Every facet has its own marker, 1..9 in the order listed.
inline Plc3 l_prism_with_split_side() {
  Plc3 p;
  const std::vector<std::array<double, 2>> xy = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (const double z : {0.0, 1.0})
    for (const auto& c : xy) p.vertices.push_back({c[0], c[1], z});
  const std::vector<std::vector<int>> loops = {{0, 5, 4, 3, 2, 1},    // 1 bottom
                                               {6, 7, 8, 9, 10, 11},  // 2 top
                                               {0, 1, 7, 6},          // 3 y = 0
                                               {1, 2, 8, 7},          // 4 x = 2
                                               {2, 3, 9, 8},          // 5 y = 1
                                               {3, 4, 9},             // 6 x = 1, lower triangle
                                               {4, 10, 9},            // 7 x = 1, upper triangle
                                               {4, 5, 11, 10},        // 8 y = 2
                                               {5, 0, 6, 11}};        // 9 x = 0
  for (std::size_t k = 0; k < loops.size(); ++k) p.facets.push_back(Facet3{{loops[k]}, static_cast<int>(k) + 1});
  return p;
}

// A box with every facet listed inside out (cavity orientation).
inline void add_inverted_box(Plc3& plc, Vec3 lo, Vec3 hi) {
  const std::size_t first = plc.facets.size();
  add_box(plc, lo, hi);
  for (std::size_t f = first; f < plc.facets.size(); ++f) {
    auto& l = plc.facets[f].loops[0];
    std::reverse(l.begin(), l.end());
  }
}

// Prism over a counter-clockwise polygon (x, y) from z = z0 to z = z1 > z0.
// Vertices: k (z0) and n + k (z1) over polygon vertex k. Facets: 0 bottom,
// 1 top, then side k over polygon edge k -> k+1 (planar exactly: two points
// repeated at two heights).
inline Plc3 prism(const std::vector<Vec2>& poly, double z0, double z1) {
  Plc3 plc;
  const int n = static_cast<int>(poly.size());
  for (const auto& p : poly) plc.vertices.push_back({p.x, p.y, z0});
  for (const auto& p : poly) plc.vertices.push_back({p.x, p.y, z1});
  Facet3 bottom, top;
  bottom.loops.emplace_back();
  top.loops.emplace_back();
  for (int k = n - 1; k >= 0; --k) bottom.loops[0].push_back(k);
  for (int k = 0; k < n; ++k) top.loops[0].push_back(n + k);
  plc.facets.push_back(bottom);
  plc.facets.push_back(top);
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    plc.facets.push_back(Facet3{{{k, k1, n + k1, n + k}}, 0});
  }
  return plc;
}

// The right prism over the polygon `xz` (in the x-z plane, counter-
// clockwise) for y in [y0, y1]: facet i is the side quad over polygon edge i,
// then the two caps (y0, y1). Unlike the fixtures above, its facets are not
// listed outward: the warping tests that use it only need make_domain, which
// orients them.
inline Plc3 prism_xz(const std::vector<std::array<double, 2>>& xz, double y0, double y1) {
  Plc3 plc;
  const int n = static_cast<int>(xz.size());
  for (const double y : {y0, y1})
    for (const auto& q : xz) plc.vertices.push_back({q[0], y, q[1]});
  for (int i = 0; i < n; ++i) {
    Facet3 f;
    f.loops.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
    plc.facets.push_back(f);
  }
  Facet3 lo, hi;
  lo.loops.emplace_back();
  hi.loops.emplace_back();
  for (int i = 0; i < n; ++i) {
    lo.loops[0].push_back(i);
    hi.loops[0].push_back(n + i);
  }
  plc.facets.push_back(lo);
  plc.facets.push_back(hi);
  return plc;
}

// The prism from z = 0 to z = h.
inline Plc3 prism(const std::vector<Vec2>& poly, double h) { return prism(poly, 0, h); }

// L-shaped prism: the L = [0,2]x[0,1] u [0,1]x[0,2], height 1 (volume 3).
inline Plc3 l_block() { return prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1); }

// [0,3]^2 x [0,1] with a square through hole [1,2]^2 (genus 1, volume 8).
// Facets: 0 bottom (outer + hole loop), 1 top, 2-5 outer walls, 6-9 hole walls.
inline Plc3 block_with_through_hole() {
  Plc3 plc;
  const Vec2 outer[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  const Vec2 inner[4] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  for (double z : {0.0, 1.0}) {
    for (const auto& p : outer) plc.vertices.push_back({p.x, p.y, z});  // 0-3 (z=0), 8-11 (z=1)
    for (const auto& p : inner) plc.vertices.push_back({p.x, p.y, z});  // 4-7 (z=0), 12-15 (z=1)
  }
  // Bottom seen from below: outer clockwise in (x, y), hole counter-clockwise.
  plc.facets.push_back(Facet3{{{0, 3, 2, 1}, {4, 5, 6, 7}}, 0});
  plc.facets.push_back(Facet3{{{8, 9, 10, 11}, {12, 15, 14, 13}}, 0});
  for (int k = 0; k < 4; ++k) {
    const int k1 = (k + 1) % 4;
    plc.facets.push_back(Facet3{{{k, k1, 8 + k1, 8 + k}}, 0});
  }
  for (int k = 0; k < 4; ++k) {  // hole walls face the hole axis
    const int k1 = (k + 1) % 4;
    plc.facets.push_back(Facet3{{{4 + k1, 4 + k, 12 + k, 12 + k1}}, 0});
  }
  return plc;
}

// The same solid with each cap given as four trapezoids (as in
// data/3d/cube_through_hole.poly), trapezoid k between outer side k -> k+1
// and the hole side below it. Facets: 0-3 bottom trapezoids (markers
// bottom[k]), 4-7 top trapezoids (markers top[k]), 8-11 outer walls, 12-15
// hole walls (marker `walls`). Vertex ids as in block_with_through_hole.
inline Plc3 block_with_through_hole_in_pieces(std::array<int, 4> bottom, std::array<int, 4> top, int walls = 0) {
  Plc3 plc = block_with_through_hole();
  std::vector<Facet3> walls_list(plc.facets.begin() + 2, plc.facets.end());
  plc.facets.clear();
  for (int k = 0; k < 4; ++k) {
    const int k1 = (k + 1) % 4;
    plc.facets.push_back(Facet3{{{4 + k, 4 + k1, k1, k}}, bottom[static_cast<std::size_t>(k)]});
  }
  for (int k = 0; k < 4; ++k) {
    const int k1 = (k + 1) % 4;
    plc.facets.push_back(Facet3{{{8 + k, 8 + k1, 12 + k1, 12 + k}}, top[static_cast<std::size_t>(k)]});
  }
  for (Facet3 f : walls_list) {
    f.marker = walls;
    plc.facets.push_back(f);
  }
  return plc;
}

// Regular octahedron |x| + |y| + |z| <= r.
inline Plc3 octahedron(double r = 1) {
  Plc3 plc;
  plc.vertices = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) {
        // (x, y, z) counter-clockwise from outside iff the sign product is positive.
        const bool even = ((sx == 1) + (sy == 3) + (sz == 5)) % 2 == 0;
        plc.facets.push_back(Facet3{{even ? std::vector<int>{sx, sy, sz} : std::vector<int>{sx, sz, sy}}, 0});
      }
  return plc;
}

// UV sphere of radius 1: `rings` latitude bands, `sectors` longitudes;
// 2 * sectors * (rings - 1) triangles.
inline Plc3 uv_sphere(int rings, int sectors) {
  Plc3 plc;
  const double pi = std::acos(-1.0);
  plc.vertices.push_back({0, 0, 1});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double t = pi * i / rings, p = 2 * pi * j / sectors;
      plc.vertices.push_back({std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)});
    }
  plc.vertices.push_back({0, 0, -1});
  const int south = static_cast<int>(plc.vertices.size()) - 1;
  auto at = [&](int i, int j) { return 1 + (i - 1) * sectors + (j % sectors); };
  for (int j = 0; j < sectors; ++j) {
    plc.facets.push_back(Facet3{{{0, at(1, j), at(1, j + 1)}}, 0});
    plc.facets.push_back(Facet3{{{south, at(rings - 1, j + 1), at(rings - 1, j)}}, 0});
  }
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      plc.facets.push_back(Facet3{{{at(i, j), at(i + 1, j), at(i + 1, j + 1)}}, 0});
      plc.facets.push_back(Facet3{{{at(i, j), at(i + 1, j + 1), at(i, j + 1)}}, 0});
    }
  return plc;
}

// Sum of the (unsigned, double) areas of facet f's triangles.
inline double facet_area(const Domain3& d, int f) {
  double a = 0;
  for (std::size_t t = 0; t < d.facet_triangles.size(); ++t)
    if (d.facet_triangle_owner[t] == f) {
      const auto& T = d.facet_triangles[t];
      const Vec3 p = d.plc.vertices[T[0]], q = d.plc.vertices[T[1]], r = d.plc.vertices[T[2]];
      a += 0.5 * norm(cross(q - p, r - p));
    }
  return a;
}

}  // namespace pqmesh::test
