// Local feature size of a polygon with holes and the size lower bound
// integral (pqmesh/lfs.hpp; thesis §1.3, Ruppert's lfs).
//
// Evaluation (LocalFeatureSize2::at). Sort the features by distance from x:
// f_1, f_2, ... (ties in any order). If k is the first index such that
// {f_1..f_k} holds a disjoint pair, then lfs(x) = d(f_k): that pair gives
// max = d(f_k), and a disjoint pair (f_i, f_j), i < j, has j >= k, so max =
// d(f_j) >= d(f_k). Sets of pairwise intersecting features are tiny (a vertex
// star, the edges of a triangular loop), so k <= 4 and only the nearest few
// features matter. We collect them ring by ring from a uniform bucket grid of
// the edges (a vertex is collected with its edges; it is never nearer than
// they are): after ring r, every uncollected edge lies outside the square of
// rings <= r, hence at distance >= L from x (L: distance to the part of the
// grid outside the square). When the k-th collected feature is at distance
// <= L - margin, no uncollected feature can come before it (their computed
// distances exceed it), so the answer equals the brute force's bit for bit.
//
// The grid only prunes; the margin (1e-10 of the coordinate magnitude, far
// above the rounding of the cell-box and distance constructions) makes the
// pruning conservative: an edge is listed in every cell whose box, inflated
// by the margin, it may meet, and L is reduced by the margin.
#include "lfs2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "pqmesh/errors.hpp"
#include "pqmesh/lfs.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {
namespace detail {

std::vector<LfsFeature> lfs_features(const Domain2& domain) {
  std::vector<LfsFeature> out;
  for (const auto& loop : domain.loops)
    for (int v : loop) out.push_back({v, -1});
  for (const auto& loop : domain.loops) {
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) out.push_back({loop[k], loop[(k + 1) % n]});
  }
  return out;
}

namespace {

struct Candidate {
  double d2;
  LfsFeature f;
};

// The squared distance d(f_k)^2 of the first feature that completes a
// disjoint pair (see the top comment), or +inf when there is none.
// `c` must be sorted by d2.
double first_disjoint_pair(const std::vector<Candidate>& c) {
  for (std::size_t k = 1; k < c.size(); ++k)
    for (std::size_t i = 0; i < k; ++i)
      if (lfs_disjoint(c[i].f, c[k].f)) return c[k].d2;
  return std::numeric_limits<double>::infinity();
}

}  // namespace
}  // namespace detail

using detail::Candidate;
using detail::LfsFeature;

double local_feature_size(const Domain2& domain, Vec2 x) {
  const auto features = detail::lfs_features(domain);
  const auto& P = domain.pslg.vertices;
  std::vector<double> d2(features.size());
  for (std::size_t i = 0; i < features.size(); ++i) d2[i] = detail::lfs_dist2(x, features[i], P);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < features.size(); ++i)
    for (std::size_t j = i + 1; j < features.size(); ++j)
      if (detail::lfs_disjoint(features[i], features[j])) best = std::min(best, std::max(d2[i], d2[j]));
  return std::sqrt(best);
}

LocalFeatureSize2::LocalFeatureSize2(const Domain2& domain) : points_(domain.pslg.vertices) {
  vertex_used_.assign(points_.size(), 0);
  for (const auto& loop : domain.loops) {
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      edges_.push_back({loop[k], loop[(k + 1) % n]});
      vertex_used_[static_cast<std::size_t>(loop[k])] = 1;
    }
  }
  lo_ = domain.bbox_min;
  const double ex = domain.bbox_max.x - lo_.x, ey = domain.bbox_max.y - lo_.y;
  const double ext = std::max({ex, ey, std::numeric_limits<double>::min()});
  const double mag = std::max({std::abs(lo_.x), std::abs(lo_.y), std::abs(domain.bbox_max.x),
                               std::abs(domain.bbox_max.y)});
  margin_ = 1e-10 * (mag + ext);
  // About one edge per cell; cells square; at most 2048 per axis.
  const double target = static_cast<double>(std::max<std::size_t>(1, edges_.size()));
  w_ = std::sqrt(std::max(ex * ey, ext * ext * 1e-6) / target);
  w_ = std::max(w_, ext / 2048.0);
  nx_ = static_cast<int>(std::floor(ex / w_)) + 1;
  ny_ = static_cast<int>(std::floor(ey / w_)) + 1;

  // Bucket the edges: edge e goes into every cell of its (inflated) bounding
  // box range whose circumscribed disk, inflated by the margin, it meets (a
  // superset of the cells whose inflated box it meets).
  const double half_diag = 0.5 * std::sqrt(2.0) * w_;
  const auto ncell = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  std::vector<std::pair<int, int>> pairs;  // (cell, edge)
  auto index = [&](double v, double l, int n) {
    const double t = std::floor((v - l) / w_);
    return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(n - 1)));
  };
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Vec2 a = points_[static_cast<std::size_t>(edges_[e].a)], b = points_[static_cast<std::size_t>(edges_[e].b)];
    const int i0 = index(std::min(a.x, b.x) - margin_, lo_.x, nx_), i1 = index(std::max(a.x, b.x) + margin_, lo_.x, nx_);
    const int j0 = index(std::min(a.y, b.y) - margin_, lo_.y, ny_), j1 = index(std::max(a.y, b.y) + margin_, lo_.y, ny_);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const Vec2 c{lo_.x + (i + 0.5) * w_, lo_.y + (j + 0.5) * w_};
        const double r = half_diag + 2 * margin_;
        if (detail::lfs_dist2_segment(c, a, b) <= r * r) pairs.emplace_back(j * nx_ + i, static_cast<int>(e));
      }
  }
  std::sort(pairs.begin(), pairs.end());
  cell_start_.assign(ncell + 1, 0);
  for (const auto& p : pairs) ++cell_start_[static_cast<std::size_t>(p.first) + 1];
  for (std::size_t c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_edges_.reserve(pairs.size());
  for (const auto& p : pairs) cell_edges_.push_back(p.second);
}

template <class F>
void LocalFeatureSize2::for_each_cell_edge(int i, int j, F&& f) const {
  const auto c = static_cast<std::size_t>(j * nx_ + i);
  for (int x = cell_start_[c]; x < cell_start_[c + 1]; ++x) f(cell_edges_[static_cast<std::size_t>(x)]);
}

double LocalFeatureSize2::at(Vec2 x) const {
  if (edges_.empty()) return std::numeric_limits<double>::infinity();
  auto index = [&](double v, double l, int n) {
    const double t = std::floor((v - l) / w_);
    return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(n - 1)));
  };
  const int ix = index(x.x, lo_.x, nx_), iy = index(x.y, lo_.y, ny_);
  // Per-thread scratch (no allocation per query once warm; at() stays const
  // and thread-safe).
  thread_local std::vector<Candidate> cand;
  thread_local std::vector<int> seen_edges, seen_vertices, ring;
  cand.clear();
  seen_edges.clear();
  seen_vertices.clear();
  const int rmax = std::max({ix, nx_ - 1 - ix, iy, ny_ - 1 - iy});
  for (int r = 0;; ++r) {
    // Edges listed in the cells of ring r, new ones only.
    ring.clear();
    const int i0 = ix - r, i1 = ix + r, j0 = iy - r, j1 = iy + r;
    for (int j = std::max(j0, 0); j <= std::min(j1, ny_ - 1); ++j) {
      if (j == j0 || j == j1) {
        for (int i = std::max(i0, 0); i <= std::min(i1, nx_ - 1); ++i)
          for_each_cell_edge(i, j, [&](int e) { ring.push_back(e); });
      } else {
        if (i0 >= 0) for_each_cell_edge(i0, j, [&](int e) { ring.push_back(e); });
        if (i1 < nx_ && i1 != i0) for_each_cell_edge(i1, j, [&](int e) { ring.push_back(e); });
      }
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    bool added = false;
    for (int e : ring) {
      if (std::binary_search(seen_edges.begin(), seen_edges.end(), e)) continue;
      seen_edges.insert(std::upper_bound(seen_edges.begin(), seen_edges.end(), e), e);
      const Edge& ed = edges_[static_cast<std::size_t>(e)];
      const LfsFeature f{ed.a, ed.b};
      cand.push_back({detail::lfs_dist2(x, f, points_), f});
      for (int v : {ed.a, ed.b}) {
        if (std::binary_search(seen_vertices.begin(), seen_vertices.end(), v)) continue;
        seen_vertices.insert(std::upper_bound(seen_vertices.begin(), seen_vertices.end(), v), v);
        const LfsFeature g{v, -1};
        cand.push_back({detail::lfs_dist2(x, g, points_), g});
      }
      added = true;
    }
    if (added)
      std::sort(cand.begin(), cand.end(), [](const Candidate& p, const Candidate& q) { return p.d2 < q.d2; });
    const double best = detail::first_disjoint_pair(cand);
    if (r >= rmax) return std::sqrt(best);  // every cell seen
    // Lower bound on the distance to anything in a cell outside the square of
    // rings <= r: the nearest of the half planes beyond its non-border sides.
    double L = std::numeric_limits<double>::infinity();
    if (i0 > 0) L = std::min(L, std::max(0.0, x.x - (lo_.x + i0 * w_)));
    if (i1 < nx_ - 1) L = std::min(L, std::max(0.0, (lo_.x + (i1 + 1) * w_) - x.x));
    if (j0 > 0) L = std::min(L, std::max(0.0, x.y - (lo_.y + j0 * w_)));
    if (j1 < ny_ - 1) L = std::min(L, std::max(0.0, (lo_.y + (j1 + 1) * w_) - x.y));
    L -= margin_;
    if (L > 0 && best <= L * L) return std::sqrt(best);
  }
}

double LocalFeatureSize2::at_vertex(int v) const {
  if (v < 0 || static_cast<std::size_t>(v) >= points_.size() || !vertex_used_[static_cast<std::size_t>(v)])
    throw InternalError("LocalFeatureSize2::at_vertex: vertex " + std::to_string(v) + " is not on a loop");
  // At x = p_v the features through v are at distance exactly 0 (see
  // lfs_dist2_segment) and pairwise intersect, so the first feature of the
  // sorted order that completes a disjoint pair is the nearest feature not
  // incident on v: at() computes exactly that.
  return at(points_[static_cast<std::size_t>(v)]);
}

// ---------------------------------------------------------------------------
// The integral of 1 / lfs^2 over P.

namespace detail {

BoundaryBuckets2::BoundaryBuckets2(const Domain2& d) : domain_(d) {
  const Vec2 lo = d.bbox_min;
  const double side = std::max(d.bbox_max.x - lo.x, d.bbox_max.y - lo.y);
  for (const auto& loop : d.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) edges_.push_back({loop[k], loop[(k + 1) % loop.size()]});
  const double mag = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(d.bbox_max.x), std::abs(d.bbox_max.y)});
  margin_ = 1e-10 * (mag + side);
  const int n = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(edges_.size()))), 1, 256);
  glo_ = lo;
  gn_ = n;
  gw_ = side > 0 ? side / n : 1.0;
  bucket_.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), {});
  const auto& P = d.pslg.vertices;
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Vec2 a = P[static_cast<std::size_t>(edges_[e][0])], b = P[static_cast<std::size_t>(edges_[e][1])];
    const int i0 = gi(std::min(a.x, b.x) - margin_, glo_.x), i1 = gi(std::max(a.x, b.x) + margin_, glo_.x);
    const int j0 = gi(std::min(a.y, b.y) - margin_, glo_.y), j1 = gi(std::max(a.y, b.y) + margin_, glo_.y);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) bucket_[static_cast<std::size_t>(j * gn_ + i)].push_back(static_cast<int>(e));
  }
  stamp_.assign(edges_.size(), -1);
}

int BoundaryBuckets2::gi(double v, double l) const {
  const double t = std::floor((v - l) / gw_);
  return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(gn_ - 1)));
}


bool BoundaryBuckets2::box_meets_boundary(Vec2 p, Vec2 q) {
  ++stamp_id_;
  const auto& P = domain_.pslg.vertices;
  const int i0 = gi(p.x - margin_, glo_.x), i1 = gi(q.x + margin_, glo_.x);
  const int j0 = gi(p.y - margin_, glo_.y), j1 = gi(q.y + margin_, glo_.y);
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i)
      for (int e : bucket_[static_cast<std::size_t>(j * gn_ + i)]) {
        if (stamp_[static_cast<std::size_t>(e)] == stamp_id_) continue;
        stamp_[static_cast<std::size_t>(e)] = stamp_id_;
        const auto& ed = edges_[static_cast<std::size_t>(e)];
        if (segment_meets_rect(P[static_cast<std::size_t>(ed[0])], P[static_cast<std::size_t>(ed[1])], p, q))
          return true;
      }
  return false;
}

// Exact point location, equal to locate(domain, s) (tests check it) but
// using the bucket grid: even-odd count of the edges crossed by the ray
// from s towards +x at height s.y + eps (symbolic: an endpoint at height
// exactly s.y counts as below the ray). Such an edge has a point (x', s.y)
// with x' >= s.x in its bounding box, so it is listed in s's row of
// buckets at a column >= s's column. Boundary when s lies on an edge
// (whose box contains s, so it is listed in s's own bucket).
Location BoundaryBuckets2::where(Vec2 s) {
  if (s.x < domain_.bbox_min.x || s.x > domain_.bbox_max.x || s.y < domain_.bbox_min.y || s.y > domain_.bbox_max.y)
    return Location::Outside;
  ++stamp_id_;
  const auto& P = domain_.pslg.vertices;
  const int i0 = gi(s.x, glo_.x), j = gi(s.y, glo_.y);
  bool inside = false;
  for (int i = i0; i < gn_; ++i)
    for (int e : bucket_[static_cast<std::size_t>(j * gn_ + i)]) {
      if (stamp_[static_cast<std::size_t>(e)] == stamp_id_) continue;
      stamp_[static_cast<std::size_t>(e)] = stamp_id_;
      const auto& ed = edges_[static_cast<std::size_t>(e)];
      Vec2 a = P[static_cast<std::size_t>(ed[0])], b = P[static_cast<std::size_t>(ed[1])];
      const Sign o = orient2d(a, b, s);
      if (o == Sign::Zero && std::min(a.x, b.x) <= s.x && s.x <= std::max(a.x, b.x) &&
          std::min(a.y, b.y) <= s.y && s.y <= std::max(a.y, b.y))
        return Location::Boundary;
      if ((a.y <= s.y) == (b.y <= s.y)) continue;  // does not cross height s.y + eps
      // Upward a -> b: the crossing is right of s iff s is left of a -> b.
      const Sign left = a.y <= s.y ? o : -o;
      if (left == Sign::Positive) inside = !inside;
    }
  return inside ? Location::Inside : Location::Outside;
}

}  // namespace detail

namespace {

enum class CellState { Unknown, Inside, Outside };

struct Integrator {
  const Domain2& domain;
  const LocalFeatureSize2& lfs;
  double refine;
  Vec2 lo;
  double side;
  detail::BoundaryBuckets2 buckets;
  LfsIntegral out{};

  static constexpr int kMaxLevel = 52;
  static constexpr int kSub = 4;  // boundary leaves: kSub x kSub midpoints

  Integrator(const Domain2& d, const LocalFeatureSize2& f, double r) : domain(d), lfs(f), refine(r), buckets(d) {
    lo = d.bbox_min;
    side = std::max(d.bbox_max.x - lo.x, d.bbox_max.y - lo.y);
  }

  // Corner coordinate k / 2^level of the root square; shared corners of cells
  // of different levels get identical doubles (scaling by 2 is exact).
  double coord(double l, std::int64_t k, int level) const {
    return l + std::ldexp(static_cast<double>(k) * side, -level);
  }

  void note_min(double v) { out.min_lfs = std::min(out.min_lfs, v); }

  // f: lfs at the corners (i, j), (i+1, j), (i+1, j+1), (i, j+1).
  void visit(int level, std::int64_t i, std::int64_t j, CellState state, const std::array<double, 4>& f) {
    const Vec2 p{coord(lo.x, i, level), coord(lo.y, j, level)};
    const Vec2 q{coord(lo.x, i + 1, level), coord(lo.y, j + 1, level)};
    const Vec2 c{coord(lo.x, 2 * i + 1, level + 1), coord(lo.y, 2 * j + 1, level + 1)};
    const double h = std::ldexp(side, -level);
    bool meets = false;
    if (state == CellState::Unknown) {
      meets = buckets.box_meets_boundary(p, q);
      if (!meets) {
        // The cell misses dP, so it is wholly inside or wholly outside, and
        // its centre is not on dP.
        state = buckets.where(c) == Location::Inside ? CellState::Inside : CellState::Outside;
      }
    }
    if (state == CellState::Outside) return;
    const double fc = lfs.at(c);
    const double m = std::min({fc, f[0], f[1], f[2], f[3]});
    if (h > refine * m && level < kMaxLevel) {
      const CellState child = meets ? CellState::Unknown : CellState::Inside;
      // V[a][b]: lfs at fine corner (2i + a, 2j + b); the edge midpoints are new.
      double V[3][3];
      V[0][0] = f[0], V[2][0] = f[1], V[2][2] = f[2], V[0][2] = f[3], V[1][1] = fc;
      V[1][0] = lfs.at({c.x, p.y});
      V[2][1] = lfs.at({q.x, c.y});
      V[1][2] = lfs.at({c.x, q.y});
      V[0][1] = lfs.at({p.x, c.y});
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di)
          visit(level + 1, 2 * i + di, 2 * j + dj, child,
                {V[di][dj], V[di + 1][dj], V[di + 1][dj + 1], V[di][dj + 1]});
      return;
    }
    if (!meets) {  // inside leaf: midpoint rule; its closed box lies in P
      out.value += h * h / (fc * fc);
      ++out.cells;
      note_min(m);
      return;
    }
    // Boundary leaf: midpoints of a kSub x kSub subdivision, located exactly.
    const double hs = h / kSub;
    bool any = false;
    for (int b = 0; b < kSub; ++b)
      for (int a = 0; a < kSub; ++a) {
        const Vec2 s{p.x + (a + 0.5) * hs, p.y + (b + 0.5) * hs};
        const Location w = buckets.where(s);
        if (w == Location::Outside) continue;
        const double fs = lfs.at(s);
        note_min(fs);
        out.value += (w == Location::Boundary ? 0.5 : 1.0) * hs * hs / (fs * fs);
        any = true;
      }
    if (any) ++out.cells;
  }
};

}  // namespace

LfsIntegral lfs_integral(const Domain2& domain, double refine) {
  if (!(refine > 0)) throw InternalError("lfs_integral: refine must be positive");
  LfsIntegral result;
  result.min_lfs = std::numeric_limits<double>::infinity();
  if (domain.loops.empty()) return result;
  const LocalFeatureSize2 lfs(domain);
  Integrator integ(domain, lfs, refine);
  integ.out.min_lfs = result.min_lfs;
  const double s = integ.side;
  const Vec2 o = integ.lo;
  integ.visit(0, 0, 0, CellState::Unknown,
              {lfs.at(o), lfs.at({o.x + s, o.y}), lfs.at({o.x + s, o.y + s}), lfs.at({o.x, o.y + s})});
  return integ.out;
}

}  // namespace pqmesh
