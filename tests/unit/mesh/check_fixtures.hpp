#pragma once
// Hand-built domains and meshes for the validity checker's tests. Domains are
// filled in directly (not through make_domain) so these tests depend only on
// the Domain2/Domain3 structs; every field the checker or locate() reads is set.
#include <algorithm>
#include <array>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"

namespace pqmesh::test {

// A polygon with holes: `outer` counter-clockwise, each hole clockwise.
// Segment ids follow the loops: loop i side k joins loops[i][k] and loops[i][k+1].
inline Domain2 polygon_domain(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                              double area) {
  Domain2 d;
  auto add_loop = [&](const std::vector<Vec2>& pts) {
    std::vector<int> loop, segs;
    const int first = static_cast<int>(d.pslg.vertices.size());
    for (std::size_t k = 0; k < pts.size(); ++k) {
      d.pslg.vertices.push_back(pts[k]);
      loop.push_back(first + static_cast<int>(k));
    }
    for (std::size_t k = 0; k < pts.size(); ++k) {
      segs.push_back(static_cast<int>(d.pslg.segments.size()));
      d.pslg.segments.push_back({loop[k], loop[(k + 1) % pts.size()]});
    }
    d.loops.push_back(loop);
    d.loop_segments.push_back(segs);
  };
  add_loop(outer);
  for (const auto& h : holes) add_loop(h);
  d.area = area;
  d.bbox_min = d.bbox_max = outer[0];
  for (const Vec2& p : d.pslg.vertices) {
    d.bbox_min = {std::min(d.bbox_min.x, p.x), std::min(d.bbox_min.y, p.y)};
    d.bbox_max = {std::max(d.bbox_max.x, p.x), std::max(d.bbox_max.y, p.y)};
  }
  return d;
}

// A domain from vertices and convex facets given as outward loops (counter-
// clockwise seen from outside P). Edges, fan triangles, normals and the box
// are derived; `shells` is one exterior shell (plus `floater_from`.. as a
// second shell when >= 0).
inline Domain3 facet_domain(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& loops,
                            double volume, int floater_from = -1) {
  Domain3 d;
  d.plc.vertices = vertices;
  for (std::size_t f = 0; f < loops.size(); ++f) {
    Facet3 facet;
    facet.loops = {loops[f]};
    facet.marker = static_cast<int>(f) + 1;
    d.plc.facets.push_back(facet);
    const auto& l = loops[f];
    for (std::size_t k = 1; k + 1 < l.size(); ++k) {
      d.facet_triangles.push_back({l[0], l[k], l[k + 1]});
      d.facet_triangle_owner.push_back(static_cast<int>(f));
    }
    const Vec3 n = cross(vertices[l[1]] - vertices[l[0]], vertices[l[2]] - vertices[l[0]]);
    d.facet_normals.push_back((1.0 / norm(n)) * n);
    for (std::size_t k = 0; k < l.size(); ++k) {
      const int a = l[k], b = l[(k + 1) % l.size()];
      DomainEdge e;
      e.a = std::min(a, b);
      e.b = std::max(a, b);
      auto it = std::find_if(d.edges.begin(), d.edges.end(), [&](const DomainEdge& x) { return x.a == e.a && x.b == e.b; });
      if (it == d.edges.end()) {
        e.facets = {static_cast<int>(f), -1};
        d.edges.push_back(e);
      } else {
        it->facets[1] = static_cast<int>(f);
      }
    }
  }
  std::sort(d.edges.begin(), d.edges.end(),
            [](const DomainEdge& x, const DomainEdge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  Shell outer;
  outer.exterior = true;
  Shell floater;
  for (int f = 0; f < static_cast<int>(loops.size()); ++f) (floater_from >= 0 && f >= floater_from ? floater : outer).facets.push_back(f);
  d.shells.push_back(outer);
  if (!floater.facets.empty()) d.shells.push_back(floater);
  d.volume = volume;
  d.bbox_min = d.bbox_max = vertices[0];
  for (const Vec3& p : vertices) {
    d.bbox_min = {std::min(d.bbox_min.x, p.x), std::min(d.bbox_min.y, p.y), std::min(d.bbox_min.z, p.z)};
    d.bbox_max = {std::max(d.bbox_max.x, p.x), std::max(d.bbox_max.y, p.y), std::max(d.bbox_max.z, p.z)};
  }
  return d;
}

// Corner v of the box [lo, hi] numbered v = i + 2j + 4k (i, j, k in {0, 1}).
inline Vec3 box_corner(Vec3 lo, Vec3 hi, int v) {
  return {(v & 1) ? hi.x : lo.x, (v & 2) ? hi.y : lo.y, (v & 4) ? hi.z : lo.z};
}

// The six outward loops of a box with corners numbered as in box_corner,
// shifted by `base`. Derived by hand: e.g. z = lo (normal -z) is 0, 2, 3, 1
// since (0,1,0) x (1,1,0) = (0,0,-1); each other loop checked the same way.
inline std::vector<std::vector<int>> box_loops(int base, bool inward = false) {
  std::vector<std::vector<int>> loops = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& l : loops) {
    for (int& v : l) v += base;
    if (inward) std::reverse(l.begin(), l.end());
  }
  return loops;
}

inline Domain3 box_domain(Vec3 lo, Vec3 hi) {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.push_back(box_corner(lo, hi, i));
  return facet_domain(v, box_loops(0), (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z));
}

// Exact for the small dyadic coordinates used here (products of a few bits):
// an independent determinant, not the checker's predicate.
inline double det6(const std::vector<Vec3>& v, const std::array<int, 4>& t) {
  const Vec3 a = v[t[0]];
  return dot(v[t[1]] - a, cross(v[t[2]] - a, v[t[3]] - a));
}

// Swap the last two vertices of t if needed so that det6 > 0.
inline std::array<int, 4> positive(const std::vector<Vec3>& v, std::array<int, 4> t) {
  if (det6(v, t) < 0) std::swap(t[2], t[3]);
  return t;
}

// Structured grid of nx x ny x nz cells of size h from lo, every cell split
// into the 6 Kuhn tetrahedra along its main diagonal (conforming across cells
// because every cell uses the same diagonal direction). Cells for which
// `skip(i, j, k)` is true are left out. Vertex (i, j, k) has id
// i + (nx+1) * (j + (ny+1) * k).
template <class Skip>
TetMesh3 kuhn_grid(int nx, int ny, int nz, Vec3 lo, double h, Skip&& skip) {
  TetMesh3 m;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.vertices.push_back({lo.x + i * h, lo.y + j * h, lo.z + k * h});
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};  // 3 even, 3 odd
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (skip(i, j, k)) continue;
        for (int p = 0; p < 6; ++p) {
          int c[3] = {i, j, k};
          std::array<int, 4> t{};
          t[0] = id(c[0], c[1], c[2]);
          for (int step = 0; step < 2; ++step) {
            ++c[perms[p][step]];
            t[step + 1] = id(c[0], c[1], c[2]);
          }
          t[3] = id(i + 1, j + 1, k + 1);
          // The path 0 -> e_p0 -> e_p0 + e_p1 -> (1,1,1) gives det = sign of the permutation.
          if (p >= 3) std::swap(t[2], t[3]);
          m.tetrahedra.push_back(t);
        }
      }
  return m;
}

template <class Skip>
TetMesh3 kuhn_grid(int n, Vec3 lo, double h, Skip&& skip) {
  return kuhn_grid(n, n, n, lo, h, skip);
}

inline TetMesh3 kuhn_grid(int n, Vec3 lo, double h) {
  return kuhn_grid(n, lo, h, [](int, int, int) { return false; });
}

}  // namespace pqmesh::test
