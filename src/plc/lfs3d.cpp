// Local feature size of a polyhedral domain and the size estimate I3(P)
// (pqmesh/lfs3.hpp; thesis §1.3, §4.8 Theorem 14). The 3D analogue of
// lfs2d.cpp, with the same evaluation argument:
//
// Evaluation (LocalFeatureSize3::at). Sort the features by distance from x:
// f_1, f_2, ... (ties in any order). If k is the first index such that
// {f_1..f_k} holds a disjoint pair, then lfs(x) = d(f_k): that pair gives max =
// d(f_k), and a disjoint pair (f_i, f_j), i < j, has j >= k, so max = d(f_j)
// >= d(f_k). Sets of pairwise intersecting features are small (the star of a
// vertex: the vertex, its edges and its facets), so only the nearest few
// features matter. We collect them shell by shell (cells at Chebyshev distance
// r from x's cell) from a uniform bucket grid of the facet triangles: a
// triangle brings its facet (provisional distance: the minimum over the
// facet's triangles collected so far), the sides of it that are edges of P
// and its corners. Every edge and vertex is part of some triangle (the facets
// are triangulated without new vertices), and a triangle that meets a cell of
// the block of shells <= r is listed there, so after shell r every triangle,
// edge and vertex not collected lies outside that block, at distance >= L from x (L:
// distance to the part of the grid outside the block). When the k-th
// candidate of the provisional order is at distance best <= L - margin:
//  - a candidate facet with provisional distance <= best is exact (its
//    uncollected triangles are computed farther than L - margin >= best);
//  - a feature whose provisional or missing distance exceeds best has true
//    computed distance > best;
// so the features at distance <= best, and their distances, are the same as
// in the brute force's list, and min over disjoint pairs of max agrees bit for
// bit (the pair realising either minimum lies among them).
//
// The grid only prunes; the margin (1e-10 of the coordinate magnitude, far
// above the rounding of the cell-box and distance constructions: the triangle
// distance uses the facet's unit normal, so its error is a few ulps of |x - a|
// even for slivers) makes the pruning conservative: a triangle is listed in
// every cell whose circumscribed ball, inflated by the margin, it may meet,
// and L is reduced by the margin.
#include "lfs3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "plc/point_location.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/lfs3.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace detail {

namespace {
using Kind = LfsFeature3::Kind;

bool contains_sorted(const std::vector<int>& v, int x) { return std::binary_search(v.begin(), v.end(), x); }
}  // namespace

LfsModel3::LfsModel3(const Domain3& d)
    : points(d.plc.vertices), triangles(d.facet_triangles), owner(d.facet_triangle_owner),
      bbox_min(d.bbox_min), bbox_max(d.bbox_max) {
  for (const auto& e : d.edges) edges.push_back({e.a, e.b});
  const std::size_t nf = d.plc.facets.size();
  vertex_used.assign(points.size(), 0);
  facet_vertices.resize(nf);
  std::vector<std::vector<int>> vertex_facets(points.size());
  for (std::size_t f = 0; f < nf; ++f) {
    auto& fv = facet_vertices[f];
    for (const auto& loop : d.plc.facets[f].loops)
      for (int v : loop) fv.push_back(v);
    std::sort(fv.begin(), fv.end());
    fv.erase(std::unique(fv.begin(), fv.end()), fv.end());
    for (int v : fv) {
      vertex_used[lfs_uz(v)] = 1;
      vertex_facets[lfs_uz(v)].push_back(static_cast<int>(f));
    }
  }
  facet_neighbours.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    auto& nb = facet_neighbours[f];
    for (int v : facet_vertices[f])
      for (int g : vertex_facets[lfs_uz(v)])
        if (g != static_cast<int>(f)) nb.push_back(g);
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  }
  // Triangles: facet CSR, oriented normals, degeneracy, sides that are edges.
  const std::size_t nt = triangles.size();
  facet_tri_start.assign(nf + 1, 0);
  for (int f : owner) ++facet_tri_start[lfs_uz(f) + 1];
  for (std::size_t f = 0; f < nf; ++f) facet_tri_start[f + 1] += facet_tri_start[f];
  facet_tris.assign(nt, -1);
  {
    std::vector<int> fill(facet_tri_start.begin(), facet_tri_start.end() - 1);
    for (std::size_t t = 0; t < nt; ++t) facet_tris[lfs_uz(fill[lfs_uz(owner[t])]++)] = static_cast<int>(t);
  }
  tri_normal.resize(nt);
  tri_degenerate.assign(nt, 0);
  tri_edges.assign(nt, {-1, -1, -1});
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tr = triangles[t];
    const Vec3 a = points[lfs_uz(tr[0])], b = points[lfs_uz(tr[1])], c = points[lfs_uz(tr[2])];
    bool degenerate = true;
    for (int drop = 0; drop < 3; ++drop) degenerate = degenerate && orient2d_projected(a, b, c, drop) == Sign::Zero;
    tri_degenerate[t] = degenerate ? 1 : 0;
    Vec3 n = d.facet_normals[lfs_uz(owner[t])];
    if (dot(cross(b - a, c - a), n) < 0) n = -1.0 * n;
    tri_normal[t] = n;
    for (int s = 0; s < 3; ++s) {
      const int u = std::min(tr[lfs_uz(s)], tr[lfs_uz((s + 1) % 3)]), v = std::max(tr[lfs_uz(s)], tr[lfs_uz((s + 1) % 3)]);
      const std::array<int, 2> key{u, v};
      const auto it = std::lower_bound(edges.begin(), edges.end(), key);
      if (it != edges.end() && *it == key) tri_edges[t][lfs_uz(s)] = static_cast<int>(it - edges.begin());
    }
  }
}

int LfsModel3::feature_count() const {
  return static_cast<int>(points.size() + edges.size() + facet_vertices.size());
}

int LfsModel3::index(LfsFeature3 f) const {
  switch (f.kind) {
    case Kind::Vertex: return f.id;
    case Kind::Edge: return vertex_count() + f.id;
    case Kind::Facet: break;
  }
  return vertex_count() + static_cast<int>(edges.size()) + f.id;
}

bool LfsModel3::disjoint(LfsFeature3 f, LfsFeature3 g) const {
  if (static_cast<int>(f.kind) > static_cast<int>(g.kind)) std::swap(f, g);  // f.kind <= g.kind
  switch (f.kind) {
    case Kind::Vertex: {
      const int v = f.id;
      if (g.kind == Kind::Vertex) return v != g.id;
      if (g.kind == Kind::Edge) return v != edges[lfs_uz(g.id)][0] && v != edges[lfs_uz(g.id)][1];
      return !contains_sorted(facet_vertices[lfs_uz(g.id)], v);
    }
    case Kind::Edge: {
      const auto& e = edges[lfs_uz(f.id)];
      if (g.kind == Kind::Edge) {
        const auto& o = edges[lfs_uz(g.id)];
        return e[0] != o[0] && e[0] != o[1] && e[1] != o[0] && e[1] != o[1];
      }
      const auto& fv = facet_vertices[lfs_uz(g.id)];
      return !contains_sorted(fv, e[0]) && !contains_sorted(fv, e[1]);
    }
    case Kind::Facet: break;
  }
  return f.id != g.id && !contains_sorted(facet_neighbours[lfs_uz(f.id)], g.id);
}

double LfsModel3::triangle_dist2(Vec3 x, int t) const {
  const auto& tr = triangles[lfs_uz(t)];
  const Vec3 a = points[lfs_uz(tr[0])], b = points[lfs_uz(tr[1])], c = points[lfs_uz(tr[2])];
  if (tri_degenerate[lfs_uz(t)])
    return std::min({lfs_dist2_segment(x, a, b), lfs_dist2_segment(x, b, c), lfs_dist2_segment(x, c, a)});
  return lfs_dist2_triangle(x, a, b, c, tri_normal[lfs_uz(t)]);
}

double LfsModel3::dist2(Vec3 x, LfsFeature3 f) const {
  switch (f.kind) {
    case Kind::Vertex: return lfs_dist2_point(x, points[lfs_uz(f.id)]);
    case Kind::Edge: return lfs_dist2_segment(x, points[lfs_uz(edges[lfs_uz(f.id)][0])], points[lfs_uz(edges[lfs_uz(f.id)][1])]);
    case Kind::Facet: break;
  }
  double best = kLfsInf;
  for (int k = facet_tri_start[lfs_uz(f.id)]; k < facet_tri_start[lfs_uz(f.id) + 1]; ++k)
    best = std::min(best, triangle_dist2(x, facet_tris[lfs_uz(k)]));
  return best;
}

std::vector<LfsFeature3> LfsModel3::features() const {
  std::vector<LfsFeature3> out;
  for (int v = 0; v < vertex_count(); ++v)
    if (vertex_used[lfs_uz(v)]) out.push_back({Kind::Vertex, v});
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) out.push_back({Kind::Edge, e});
  for (int f = 0; f < static_cast<int>(facet_vertices.size()); ++f) out.push_back({Kind::Facet, f});
  return out;
}

namespace {

struct Candidate {
  double d2;
  LfsFeature3 f;
};

// The squared distance d(f_k)^2 of the first candidate that completes a
// disjoint pair (see the top comment) among the first n, or +inf. c[0..n)
// must be the n nearest candidates, sorted by d2.
double first_disjoint_pair(const LfsModel3& m, const std::vector<Candidate>& c, std::size_t n) {
  for (std::size_t k = 1; k < n; ++k)
    for (std::size_t i = 0; i < k; ++i)
      if (m.disjoint(c[i].f, c[k].f)) return c[k].d2;
  return kLfsInf;
}

}  // namespace
}  // namespace detail

using detail::Candidate;
using detail::LfsFeature3;
using detail::LfsModel3;
using Kind = LfsFeature3::Kind;

double local_feature_size(const Domain3& domain, Vec3 x) {
  const LfsModel3 m(domain);
  const auto features = m.features();
  std::vector<double> d2(features.size());
  for (std::size_t i = 0; i < features.size(); ++i) d2[i] = m.dist2(x, features[i]);
  double best = detail::kLfsInf;
  for (std::size_t i = 0; i < features.size(); ++i)
    for (std::size_t j = i + 1; j < features.size(); ++j)
      if (m.disjoint(features[i], features[j])) best = std::min(best, std::max(d2[i], d2[j]));
  return std::sqrt(best);
}

// ---------------------------------------------------------------------------
// The grid evaluator.

struct LocalFeatureSize3::Impl {
  LfsModel3 model;
  Vec3 lo{};
  double w = 1, margin = 0;
  std::array<int, 3> n{1, 1, 1};
  std::vector<int> cell_start, cell_tris;  // CSR: cell -> triangles

  explicit Impl(const Domain3& d);
  int index(double v, int axis) const {
    const double t = std::floor((v - axis_coord(lo, axis)) / w);
    return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(n[detail::lfs_uz(axis)] - 1)));
  }
  int flat(int i, int j, int k) const { return (k * n[1] + j) * n[0] + i; }
  double at(Vec3 x) const;
};

LocalFeatureSize3::Impl::Impl(const Domain3& d) : model(d) {
  using detail::lfs_uz;
  lo = d.bbox_min;
  const Vec3 hi = d.bbox_max;
  const double ex = hi.x - lo.x, ey = hi.y - lo.y, ez = hi.z - lo.z;
  const double ext = std::max({ex, ey, ez, std::numeric_limits<double>::min()});
  const double mag = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                               std::abs(hi.z)});
  margin = 1e-10 * (mag + ext);
  // About two cells per triangle, cubic cells, at most 256 per axis.
  const double target = 2.0 * static_cast<double>(std::max<std::size_t>(1, model.triangles.size()));
  w = std::cbrt(std::max(ex * ey * ez, ext * ext * ext * 1e-9) / target);
  w = std::max(w, ext / 256.0);
  n = {static_cast<int>(std::floor(ex / w)) + 1, static_cast<int>(std::floor(ey / w)) + 1,
       static_cast<int>(std::floor(ez / w)) + 1};
  const double r = 0.5 * std::sqrt(3.0) * w + 3 * margin;
  const std::size_t ncell = lfs_uz(n[0]) * lfs_uz(n[1]) * lfs_uz(n[2]);
  std::vector<std::pair<int, int>> pairs;  // (cell, triangle)
  for (std::size_t t = 0; t < model.triangles.size(); ++t) {
    const auto& tr = model.triangles[t];
    std::array<int, 3> i0{}, i1{};
    for (int ax = 0; ax < 3; ++ax) {
      double mn = detail::kLfsInf, mx = -detail::kLfsInf;
      for (int v : tr) {
        mn = std::min(mn, axis_coord(model.points[lfs_uz(v)], ax));
        mx = std::max(mx, axis_coord(model.points[lfs_uz(v)], ax));
      }
      i0[lfs_uz(ax)] = index(mn - margin, ax);
      i1[lfs_uz(ax)] = index(mx + margin, ax);
    }
    for (int k = i0[2]; k <= i1[2]; ++k)
      for (int j = i0[1]; j <= i1[1]; ++j)
        for (int i = i0[0]; i <= i1[0]; ++i) {
          const Vec3 c{lo.x + (i + 0.5) * w, lo.y + (j + 0.5) * w, lo.z + (k + 0.5) * w};
          if (model.triangle_dist2(c, static_cast<int>(t)) <= r * r) pairs.emplace_back(flat(i, j, k), static_cast<int>(t));
        }
  }
  std::sort(pairs.begin(), pairs.end());
  cell_start.assign(ncell + 1, 0);
  for (const auto& p : pairs) ++cell_start[lfs_uz(p.first) + 1];
  for (std::size_t c = 0; c < ncell; ++c) cell_start[c + 1] += cell_start[c];
  cell_tris.reserve(pairs.size());
  for (const auto& p : pairs) cell_tris.push_back(p.second);
}

double LocalFeatureSize3::Impl::at(Vec3 x) const {
  using detail::lfs_uz;
  if (model.triangles.empty()) return detail::kLfsInf;
  const std::array<int, 3> ix{index(x.x, 0), index(x.y, 1), index(x.z, 2)};
  // Per-thread scratch, reset by a generation counter (no allocation per
  // query once warm; at() stays const and thread-safe).
  thread_local std::vector<Candidate> cand;
  thread_local std::vector<double> fd2;         // provisional distance per feature index
  thread_local std::vector<std::uint64_t> fgen, tgen;
  thread_local std::uint64_t gen = 0;
  const auto nfeat = lfs_uz(model.feature_count()), ntri = model.triangles.size();
  if (fd2.size() < nfeat) {
    fd2.resize(nfeat);
    fgen.resize(nfeat, 0);
  }
  if (tgen.size() < ntri) tgen.resize(ntri, 0);
  ++gen;
  cand.clear();
  // Set when a shell adds a candidate or lowers a provisional distance:
  // otherwise the candidates and their distances are those of the previous
  // shell, and so is `best` (the minimum over disjoint candidate pairs of the
  // larger distance, whatever the order of ties; see first_disjoint_pair).
  bool changed = false;
  auto offer = [&](LfsFeature3 f, double d2) {
    const auto id = lfs_uz(model.index(f));
    if (fgen[id] != gen) {
      fgen[id] = gen;
      fd2[id] = d2;
      cand.push_back({d2, f});
      changed = true;
    } else if (d2 < fd2[id]) {
      fd2[id] = d2;
      changed = true;
    }
  };
  auto take = [&](int t) {
    if (tgen[lfs_uz(t)] == gen) return;
    tgen[lfs_uz(t)] = gen;
    const auto& tr = model.triangles[lfs_uz(t)];
    offer({Kind::Facet, model.owner[lfs_uz(t)]}, model.triangle_dist2(x, t));
    for (int s = 0; s < 3; ++s) {
      const int e = model.tri_edges[lfs_uz(t)][lfs_uz(s)];
      if (e >= 0 && fgen[lfs_uz(model.index({Kind::Edge, e}))] != gen) offer({Kind::Edge, e}, model.dist2(x, {Kind::Edge, e}));
      const int v = tr[lfs_uz(s)];
      if (fgen[lfs_uz(v)] != gen) offer({Kind::Vertex, v}, detail::lfs_dist2_point(x, model.points[lfs_uz(v)]));
    }
  };
  auto cell = [&](int i, int j, int k) {
    const auto c = lfs_uz(flat(i, j, k));
    for (int q = cell_start[c]; q < cell_start[c + 1]; ++q) take(cell_tris[lfs_uz(q)]);
  };
  const int rmax = std::max({ix[0], n[0] - 1 - ix[0], ix[1], n[1] - 1 - ix[1], ix[2], n[2] - 1 - ix[2]});
  double best = detail::kLfsInf;
  for (int r = 0;; ++r) {
    const int i0 = ix[0] - r, i1 = ix[0] + r, j0 = ix[1] - r, j1 = ix[1] + r, k0 = ix[2] - r, k1 = ix[2] + r;
    for (int k = std::max(k0, 0); k <= std::min(k1, n[2] - 1); ++k)
      for (int j = std::max(j0, 0); j <= std::min(j1, n[1] - 1); ++j) {
        if (k == k0 || k == k1 || j == j0 || j == j1) {
          for (int i = std::max(i0, 0); i <= std::min(i1, n[0] - 1); ++i) cell(i, j, k);
        } else {
          if (i0 >= 0) cell(i0, j, k);
          if (i1 < n[0] && i1 != i0) cell(i1, j, k);
        }
      }
    if (changed) {
      changed = false;
      // Provisional facet distances may have dropped: refresh, then sort.
      for (auto& c : cand) c.d2 = fd2[lfs_uz(model.index(c.f))];
      // Only a short sorted prefix is usually needed (k is small): sort the
      // nearest few, fall back to the full order when no pair completes there.
      const auto by_d2 = [](const Candidate& p, const Candidate& q) { return p.d2 < q.d2; };
      const std::size_t head = std::min<std::size_t>(cand.size(), 24);
      std::partial_sort(cand.begin(), cand.begin() + static_cast<std::ptrdiff_t>(head), cand.end(), by_d2);
      best = detail::first_disjoint_pair(model, cand, head);
      if (best == detail::kLfsInf && head < cand.size()) {
        std::sort(cand.begin(), cand.end(), by_d2);
        best = detail::first_disjoint_pair(model, cand, cand.size());
      }
    }
    if (r >= rmax) return std::sqrt(best);  // every cell seen
    // Lower bound on the distance to anything in a cell outside the block of
    // shells <= r: the nearest of the half spaces beyond its non-border faces.
    double L = detail::kLfsInf;
    const std::array<int, 3> a0{i0, j0, k0}, a1{i1, j1, k1};
    for (int ax = 0; ax < 3; ++ax) {
      const double xa = axis_coord(x, ax), la = axis_coord(lo, ax);
      if (a0[lfs_uz(ax)] > 0) L = std::min(L, std::max(0.0, xa - (la + a0[lfs_uz(ax)] * w)));
      if (a1[lfs_uz(ax)] < n[lfs_uz(ax)] - 1) L = std::min(L, std::max(0.0, (la + (a1[lfs_uz(ax)] + 1) * w) - xa));
    }
    L -= margin;
    if (L > 0 && best <= L * L) return std::sqrt(best);
  }
}

LocalFeatureSize3::LocalFeatureSize3(const Domain3& domain) : impl_(std::make_unique<Impl>(domain)) {}
LocalFeatureSize3::~LocalFeatureSize3() = default;
LocalFeatureSize3::LocalFeatureSize3(LocalFeatureSize3&&) noexcept = default;
LocalFeatureSize3& LocalFeatureSize3::operator=(LocalFeatureSize3&&) noexcept = default;

double LocalFeatureSize3::at(Vec3 x) const { return impl_->at(x); }

double LocalFeatureSize3::at_vertex(int v) const {
  const auto& m = impl_->model;
  if (v < 0 || v >= m.vertex_count() || !m.vertex_used[detail::lfs_uz(v)])
    throw InternalError("LocalFeatureSize3::at_vertex: vertex " + std::to_string(v) + " is not on a facet");
  // At x = p_v the features through v are at distance ~0 (exactly 0 for
  // vertices and edges, a few ulps for a facet's plane) and pairwise
  // intersect, so the first feature that completes a disjoint pair is the
  // nearest feature not incident on v.
  return at(m.points[detail::lfs_uz(v)]);
}

int LocalFeatureSize3::grid_cells(int axis) const { return impl_->n[detail::lfs_uz(std::clamp(axis, 0, 2))]; }

}  // namespace pqmesh
