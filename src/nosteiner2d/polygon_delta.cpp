// Thesis §5.1 "Delta" (before Theorem 28), used by §5.2 to shrink Q to R.
//
// delta(V) for a vertex: distance to the closest face not containing V (the
// other vertices and the sides not at V). delta(E) for a side E = pq: the
// minimum of delta(p), delta(q) and the distance from E to the closest face
// disjoint from E (vertices other than p, q; sides sharing no end with E).
// Deviation (docs/algorithm/nosteiner2d.md "Delta and the shrink to R"):
// Euclidean distance, a lower bound of the thesis's geodesic distance inside
// the polygon. With it R is shrunk by at most as much as the thesis asks, so R
// stays inside Q, and Theorem 30's argument (triangle inequality only) goes
// through for Euclidean delta.
//
// A bucket grid proposes only faces within the current upper bound: every
// face starts with a bound from a neighbouring disjoint face (the vertex two
// steps along the loop), so only nearby buckets are read. Distances and the
// grid are floating-point measurements; nothing here is a branch of the
// algorithm's combinatorics.
#include <algorithm>
#include <cmath>
#include <limits>

#include "nosteiner2d/stages.hpp"

namespace pqmesh {

namespace {

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  double t = len2 > 0 ? dot(p - a, d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec2 f{a.x + t * d.x, a.y + t * d.y};
  return std::hypot(p.x - f.x, p.y - f.y);
}

// Distance between two non-crossing segments (faces of a simple polygon meet
// at most at shared ends, and this is only called for disjoint faces).
double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}

struct FlatSide {
  int loop, k;  // side k -> k+1 of loop
  Vec2 a, b;
};

class SideGrid {
 public:
  explicit SideGrid(const std::vector<FlatSide>& sides) : sides_(sides) {
    lo_ = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    Vec2 hi{-lo_.x, -lo_.y};
    double total = 0;
    for (const auto& s : sides) {
      lo_ = {std::min({lo_.x, s.a.x, s.b.x}), std::min({lo_.y, s.a.y, s.b.y})};
      hi = {std::max({hi.x, s.a.x, s.b.x}), std::max({hi.y, s.a.y, s.b.y})};
      total += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
    }
    const double extent = std::max(hi.x - lo_.x, hi.y - lo_.y);
    cell_ = std::max(total / double(std::max<std::size_t>(sides.size(), 1)), extent / 1024.0);
    if (!(cell_ > 0)) cell_ = 1;
    nx_ = std::max(1, int((hi.x - lo_.x) / cell_) + 1);
    ny_ = std::max(1, int((hi.y - lo_.y) / cell_) + 1);
    cells_.assign(std::size_t(nx_) * std::size_t(ny_), {});
    stamp_.assign(sides.size(), -1);
    for (int i = 0; i < int(sides.size()); ++i) {
      const auto [x0, y0] = cell(std::min(sides[std::size_t(i)].a.x, sides[std::size_t(i)].b.x),
                                 std::min(sides[std::size_t(i)].a.y, sides[std::size_t(i)].b.y));
      const auto [x1, y1] = cell(std::max(sides[std::size_t(i)].a.x, sides[std::size_t(i)].b.x),
                                 std::max(sides[std::size_t(i)].a.y, sides[std::size_t(i)].b.y));
      for (int x = x0; x <= x1; ++x)
        for (int y = y0; y <= y1; ++y) cells_[std::size_t(x) * std::size_t(ny_) + std::size_t(y)].push_back(i);
    }
  }
  // Every side whose bounding box meets [lo - r, hi + r] (and possibly more).
  template <class F>
  void visit(Vec2 lo, Vec2 hi, double r, F&& f) {
    ++query_;
    const auto [x0, y0] = cell(lo.x - r, lo.y - r);
    const auto [x1, y1] = cell(hi.x + r, hi.y + r);
    for (int x = x0; x <= x1; ++x)
      for (int y = y0; y <= y1; ++y)
        for (int i : cells_[std::size_t(x) * std::size_t(ny_) + std::size_t(y)]) {
          if (stamp_[std::size_t(i)] == query_) continue;
          stamp_[std::size_t(i)] = query_;
          f(sides_[std::size_t(i)]);
        }
  }

 private:
  std::pair<int, int> cell(double x, double y) const {
    const double fx = std::floor((x - lo_.x) / cell_), fy = std::floor((y - lo_.y) / cell_);
    return {int(std::clamp(fx, 0.0, double(nx_ - 1))), int(std::clamp(fy, 0.0, double(ny_ - 1)))};
  }
  const std::vector<FlatSide>& sides_;
  Vec2 lo_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
  std::vector<int> stamp_;
  int query_ = 0;
};

}  // namespace

PolygonDelta polygon_delta(const std::vector<std::vector<Vec2>>& loops) {
  PolygonDelta out;
  std::vector<FlatSide> sides;
  for (int l = 0; l < int(loops.size()); ++l) {
    const auto& lp = loops[std::size_t(l)];
    for (int k = 0; k < int(lp.size()); ++k)
      sides.push_back({l, k, lp[std::size_t(k)], lp[(std::size_t(k) + 1) % lp.size()]});
  }
  SideGrid grid(sides);
  out.vertex.resize(loops.size());
  out.side.resize(loops.size());
  // Vertices. A side (l, j) -> (l, j+1) contains vertex (l, k) iff j == k or
  // j + 1 == k (mod n); any other side is disjoint from it, and so are both
  // of its ends except (l, k) itself. Visiting every side nearby covers the
  // vertices too (each vertex is an end of a side).
  for (int l = 0; l < int(loops.size()); ++l) {
    const auto& lp = loops[std::size_t(l)];
    const int n = int(lp.size());
    out.vertex[std::size_t(l)].assign(std::size_t(n), 0.0);
    for (int k = 0; k < n; ++k) {
      const Vec2 v = lp[std::size_t(k)];
      const Vec2 nb = lp[std::size_t((k + 1) % n)], pb = lp[std::size_t((k + n - 1) % n)];
      double best = std::min(std::hypot(nb.x - v.x, nb.y - v.y), std::hypot(pb.x - v.x, pb.y - v.y));
      grid.visit(v, v, best, [&](const FlatSide& s) {
        const bool same = s.loop == l;
        const bool at_v = same && (s.k == k || (s.k + 1) % n == k);
        if (!at_v) {
          best = std::min(best, point_segment_distance(v, s.a, s.b));
        } else {
          // Only the far end of a side at V is disjoint from V.
          const Vec2 far = s.k == k ? s.b : s.a;
          best = std::min(best, std::hypot(far.x - v.x, far.y - v.y));
        }
      });
      out.vertex[std::size_t(l)][std::size_t(k)] = best;
    }
  }
  // Sides.
  for (int l = 0; l < int(loops.size()); ++l) {
    const auto& lp = loops[std::size_t(l)];
    const int n = int(lp.size());
    out.side[std::size_t(l)].assign(std::size_t(n), 0.0);
    for (int k = 0; k < n; ++k) {
      const int k1 = (k + 1) % n;
      const Vec2 p = lp[std::size_t(k)], q = lp[std::size_t(k1)];
      double best = std::min(out.vertex[std::size_t(l)][std::size_t(k)], out.vertex[std::size_t(l)][std::size_t(k1)]);
      const Vec2 lo{std::min(p.x, q.x), std::min(p.y, q.y)}, hi{std::max(p.x, q.x), std::max(p.y, q.y)};
      grid.visit(lo, hi, best, [&](const FlatSide& s) {
        if (s.loop == l && s.k == k) return;
        const bool before = s.loop == l && (s.k + 1) % n == k;  // shares p
        const bool after = s.loop == l && s.k == k1;            // shares q
        if (before && after) return;                            // a triangle loop: both ends shared
        if (before) {
          best = std::min(best, point_segment_distance(s.a, p, q));
        } else if (after) {
          best = std::min(best, point_segment_distance(s.b, p, q));
        } else {
          best = std::min(best, segment_distance(p, q, s.a, s.b));
        }
      });
      out.side[std::size_t(l)][std::size_t(k)] = best;
    }
  }
  return out;
}

std::vector<std::vector<Vec2>> q_loop_points(const PolygonQ& q) {
  std::vector<std::vector<Vec2>> out;
  for (const auto& loop : q.loops) {
    out.emplace_back();
    for (int id : loop) out.back().push_back(q.wedges.vertices[std::size_t(id)]);
  }
  return out;
}

}  // namespace pqmesh
