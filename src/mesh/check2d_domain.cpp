// Stage 4 of the triangle-mesh checker (see check2d.cpp): input vertices found
// by exact coordinates, input segments walked along mesh edges, the boundary
// compared with the domain's loops, Steiner points on the boundary, and the
// locate() second opinion.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/check2d_stages.hpp"
#include "plc/point_location2.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::detail::check2d {

namespace {

// The closed segment uw meets the closed rectangle [x0, x1] x [y0, y1]. Exact:
// both are convex, so they are disjoint iff an axis or the segment's line
// separates them (orient2d on the four corners).
bool segment_meets_cell(Vec2 u, Vec2 w, double x0, double x1, double y0, double y1) {
  if (std::max(u.x, w.x) < x0 || std::min(u.x, w.x) > x1 || std::max(u.y, w.y) < y0 || std::min(u.y, w.y) > y1)
    return false;
  int pos = 0, neg = 0;
  for (const Vec2 q : {Vec2{x0, y0}, Vec2{x1, y0}, Vec2{x1, y1}, Vec2{x0, y1}}) {
    const Sign s = orient2d(u, w, q);
    pos += s == Sign::Positive;
    neg += s == Sign::Negative;
  }
  return pos < 4 && neg < 4;
}

// DomainLocator2's answers for many points, mostly without its edge scans: a
// g x g grid of closed cells over the domain's bounding box. A cell that meets
// no loop edge lies inside P or outside P as a whole (it is connected and
// misses dP), which locating one of its corners tells once. A point that exact
// comparisons place in such a cell is not on dP and lies on the same side as
// that corner, so it takes the cell's answer; every other point (in a cell
// that meets an edge, or where the rounded cell index misses) is located by
// DomainLocator2 itself. The answers are therefore exactly DomainLocator2's.
class CellLocator {
 public:
  CellLocator(const Domain2& d, std::size_t points) : locator_(d) {
    const Vec2 lo = d.bbox_min, hi = d.bbox_max;
    if (d.loops.empty() || !(hi.x > lo.x) || !(hi.y > lo.y)) return;
    const auto& P = d.pslg.vertices;
    // About 16 points per cell; fewer cells while the edges' bounding boxes
    // would cover too many (long slanted edges), so building stays linear.
    g_ = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(points) / 16), 1.0, 1024.0));
    for (;; g_ /= 2) {
      std::size_t covered = 0;
      for (const auto& loop : d.loops)
        for (std::size_t k = 0; k < loop.size(); ++k) {
          const Vec2 u = P[static_cast<std::size_t>(loop[k])], w = P[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
          const auto [i0, i1] = range(std::min(u.x, w.x), std::max(u.x, w.x), lo.x, hi.x);
          const auto [j0, j1] = range(std::min(u.y, w.y), std::max(u.y, w.y), lo.y, hi.y);
          covered += static_cast<std::size_t>(i1 - i0 + 1) * static_cast<std::size_t>(j1 - j0 + 1);
        }
      if (g_ == 1 || covered <= 4 * points + static_cast<std::size_t>(g_) * static_cast<std::size_t>(g_)) break;
    }
    xs_.resize(static_cast<std::size_t>(g_) + 1);
    ys_.resize(static_cast<std::size_t>(g_) + 1);
    for (int i = 0; i <= g_; ++i) {  // non-decreasing; the ends exactly the box
      xs_[static_cast<std::size_t>(i)] = i == g_ ? hi.x : lo.x + (hi.x - lo.x) * i / g_;
      ys_[static_cast<std::size_t>(i)] = i == g_ ? hi.y : lo.y + (hi.y - lo.y) * i / g_;
    }
    cell_.assign(static_cast<std::size_t>(g_) * static_cast<std::size_t>(g_), kUnknown);
    for (const auto& loop : d.loops)
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Vec2 u = P[static_cast<std::size_t>(loop[k])], w = P[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
        const auto [i0, i1] = range(std::min(u.x, w.x), std::max(u.x, w.x), lo.x, hi.x);
        const auto [j0, j1] = range(std::min(u.y, w.y), std::max(u.y, w.y), lo.y, hi.y);
        for (int i = i0; i <= i1; ++i)
          for (int j = j0; j <= j1; ++j) {
            std::uint8_t& c = cell_[index(i, j)];
            if (c != kCrossed && segment_meets_cell(u, w, x(i), x(i + 1), y(j), y(j + 1))) c = kCrossed;
          }
      }
    // Two uncrossed cells with a common side form a connected set that
    // misses dP, so they lie on the same side: one location per connected
    // region of uncrossed cells (4-neighbours), spread by a flood fill.
    std::vector<std::size_t> stack;
    for (int i = 0; i < g_; ++i)
      for (int j = 0; j < g_; ++j) {
        if (cell_[index(i, j)] != kUnknown) continue;
        const Location where = locator_.locate({x(i), y(j)});
        const std::uint8_t label =
            where == Location::Inside ? kInside : where == Location::Outside ? kOutside : kCrossed;
        if (label == kCrossed) {  // cannot happen for a closed cell missing dP; kept as the safe answer
          cell_[index(i, j)] = kCrossed;
          continue;
        }
        cell_[index(i, j)] = label;
        stack.assign(1, index(i, j));
        while (!stack.empty()) {
          const std::size_t c = stack.back();
          stack.pop_back();
          const auto g = static_cast<std::size_t>(g_);
          const int ci = static_cast<int>(c / g), cj = static_cast<int>(c % g);
          const int ni[4] = {ci - 1, ci + 1, ci, ci}, nj[4] = {cj, cj, cj - 1, cj + 1};
          for (int k = 0; k < 4; ++k) {
            if (ni[k] < 0 || ni[k] >= g_ || nj[k] < 0 || nj[k] >= g_) continue;
            std::uint8_t& n = cell_[index(ni[k], nj[k])];
            if (n != kUnknown) continue;
            n = label;
            stack.push_back(index(ni[k], nj[k]));
          }
        }
      }
  }

  Location locate(Vec2 p) const {
    if (g_ > 0) {
      const int i = guess(p.x, xs_.front(), xs_.back()), j = guess(p.y, ys_.front(), ys_.back());
      if (x(i) <= p.x && p.x <= x(i + 1) && y(j) <= p.y && p.y <= y(j + 1)) {
        const std::uint8_t c = cell_[index(i, j)];
        if (c == kInside) return Location::Inside;
        if (c == kOutside) return Location::Outside;
      }
    }
    return locator_.locate(p);
  }

 private:
  static constexpr std::uint8_t kUnknown = 0, kCrossed = 1, kInside = 2, kOutside = 3;

  double x(int i) const { return xs_[static_cast<std::size_t>(i)]; }
  double y(int j) const { return ys_[static_cast<std::size_t>(j)]; }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(i) * static_cast<std::size_t>(g_) + static_cast<std::size_t>(j); }
  // The cell column (row) of v, rounded; callers check it exactly.
  int guess(double v, double lo, double hi) const {
    const double t = std::floor((v - lo) / (hi - lo) * g_);
    return t >= 0 ? (t < g_ - 1 ? static_cast<int>(t) : g_ - 1) : 0;
  }
  // The cells that [a, b] may meet, one extra on each side for the rounding.
  std::array<int, 2> range(double a, double b, double lo, double hi) const {
    return {std::max(guess(a, lo, hi) - 1, 0), std::min(guess(b, lo, hi) + 1, g_ - 1)};
  }

  const DomainLocator2 locator_;
  int g_ = 0;
  std::vector<double> xs_, ys_;
  std::vector<std::uint8_t> cell_;
};

}  // namespace

void Checker2::map_input_vertices(const Domain2& d) {
  const auto& pv = d.pslg.vertices;
  std::vector<char> referenced(pv.size(), 0);
  for (const auto& s : d.pslg.segments)
    for (int v : s)
      if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
  for (const auto& loop : d.loops)
    for (int v : loop)
      if (v >= 0 && v < static_cast<int>(pv.size())) referenced[v] = 1;
  int unreferenced = 0;
  if (coincident_) {
    unreferenced = map_input_vertices_by_coordinates(sink_, m_.vertices, order_, pv, referenced, in2mesh_, mesh2in_);
  } else {
    // No two mesh vertices coincide: the mesh vertex at an input vertex's
    // coordinates is unique. One scan of the mesh vertices against a hash
    // table of the input vertices (first of equal ones; exact comparisons).
    std::size_t size = 16;
    while (size < 2 * pv.size()) size *= 2;
    const std::size_t mask = size - 1;
    std::vector<int> table(size, -1), first(pv.size()), at(pv.size(), -1);
    auto slot = [&](Vec2 p) {
      std::size_t s = coordinate_hash(p) & mask;
      while (table[s] >= 0 && !(pv[static_cast<std::size_t>(table[s])] == p)) s = (s + 1) & mask;
      return s;
    };
    for (std::size_t i = 0; i < pv.size(); ++i) {
      const std::size_t s = slot(pv[i]);
      if (table[s] < 0) table[s] = static_cast<int>(i);
      first[i] = table[s];
    }
    for (std::size_t v = 0; v < m_.vertices.size(); ++v) {
      const int i = table[slot(m_.vertices[v])];
      if (i >= 0) at[static_cast<std::size_t>(i)] = static_cast<int>(v);
    }
    unreferenced = map_input_vertices_with(sink_, m_.vertices.size(), pv, referenced, in2mesh_, mesh2in_,
                                           [&](std::size_t i) { return at[static_cast<std::size_t>(first[i])]; });
  }
  if (unreferenced)
    sink_.note(std::to_string(unreferenced) + " input vertices on no segment were not required to be mesh vertices");
}

void Checker2::walk_segments(const Domain2& d) {
  const auto& pv = d.pslg.vertices;
  const std::size_t ns = d.pslg.segments.size();
  chain_offset_.assign(ns + 1, 0);
  chain_items_.clear();
  segment_ok_.assign(ns, 0);
  int skipped = 0;
  for (std::size_t s = 0; s < ns; ++s) {
    chain_offset_[s] = static_cast<int>(chain_items_.size());
    const auto& seg = d.pslg.segments[s];
    const bool ids_ok = seg[0] >= 0 && seg[1] >= 0 && seg[0] < static_cast<int>(pv.size()) &&
                        seg[1] < static_cast<int>(pv.size());
    const int A = ids_ok ? in2mesh_[seg[0]] : -1, B = ids_ok ? in2mesh_[seg[1]] : -1;
    if (A < 0 || B < 0) {
      ++skipped;
      continue;
    }
    const Vec2 pa = m_.vertices[A], pb = m_.vertices[B];
    const std::string name = "input segment " + std::to_string(s) + " (" + format_ids(seg) + ")";
    const ChainWalk walk = walk_chain(adjacency_, A, B, [&](int c, int w) {
      // The cheap test first: the vertex the walk came from is also near the
      // segment, and near_segment on such points needs exact arithmetic.
      const Vec2 p = m_.vertices[w];
      return dot_sign(p, m_.vertices[c], pb) == Sign::Negative && near_segment(p, pa, pb);
    });
    const int c = walk.chain.back();
    if (walk.end == ChainWalk::End::Stuck) {
      sink_.add(CheckKind::MissingEdge, {static_cast<std::int64_t>(s)},
                name + " is not a chain of mesh edges: no mesh edge continues along it from mesh vertex " +
                    std::to_string(c) + " at " + format_point(m_.vertices[c]) + " towards mesh vertex " +
                    std::to_string(B));
      continue;
    }
    if (walk.end == ChainWalk::End::Forked) {
      sink_.add(CheckKind::NonConforming, {c, walk.next, walk.other},
                "mesh edges from vertex " + std::to_string(c) + " to " + std::to_string(walk.next) + " and " +
                    std::to_string(walk.other) + " both run along " + name + " (overlapping edges)");
      continue;
    }
    segment_ok_[s] = 1;
    chain_items_.insert(chain_items_.end(), walk.chain.begin(), walk.chain.end());
  }
  chain_offset_[ns] = static_cast<int>(chain_items_.size());
  if (skipped) sink_.note(std::to_string(skipped) + " input segment(s) not walked because an endpoint is missing");
}

// Stage 4 (b) of check2d.cpp: the boundary edges against the loops, sides replaced by their chains.
void Checker2::check_boundary_chain(const Domain2& d) {
  // Segment lookup by endpoints.
  std::vector<std::array<int, 3>> seg_index;  // lo, hi, segment
  for (std::size_t s = 0; s < d.pslg.segments.size(); ++s) {
    const auto& e = d.pslg.segments[s];
    seg_index.push_back({std::min(e[0], e[1]), std::max(e[0], e[1]), static_cast<int>(s)});
  }
  std::sort(seg_index.begin(), seg_index.end());
  struct R {
    int lo, hi, weight;
    int source;  // >= 0: boundary edge index; < 0: -1 - segment id
  };
  std::vector<R> recs;
  for (const auto& loop : d.loops) {
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int u = loop[k], v = loop[(k + 1) % n];
      const std::array<int, 3> key{std::min(u, v), std::max(u, v), -1};
      auto it = std::lower_bound(seg_index.begin(), seg_index.end(), key);
      if (it == seg_index.end() || (*it)[0] != key[0] || (*it)[1] != key[1])
        throw DomainError(ErrorCode::InvalidPolygon,
                          "inconsistent Domain2: loop side (" + std::to_string(u) + " " + std::to_string(v) +
                              ") is not an input segment (build domains with make_domain)",
                          {u, v});
      const int s = (*it)[2];
      if (!segment_ok_[s]) {
        sink_.note("boundary not compared with the domain: input segment " + std::to_string(s) + " is missing");
        return;
      }
      const bool along = d.pslg.segments[s][0] == u;
      for (int j = chain_offset_[s]; j + 1 < chain_offset_[s + 1]; ++j) {
        int x = chain_items_[j], y = chain_items_[j + 1];
        if (!along) std::swap(x, y);
        recs.push_back(x < y ? R{x, y, -1, -1 - s} : R{y, x, 1, -1 - s});
      }
    }
  }
  for (std::size_t i = 0; i < boundary_.size(); ++i) {
    const int x = boundary_[i][0], y = boundary_[i][1];
    recs.push_back(x < y ? R{x, y, 1, static_cast<int>(i)} : R{y, x, -1, static_cast<int>(i)});
  }
  std::sort(recs.begin(), recs.end(), [](const R& a, const R& b) {
    if (a.lo != b.lo) return a.lo < b.lo;
    if (a.hi != b.hi) return a.hi < b.hi;
    return a.source < b.source;
  });
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i;
    int sum = 0, edge = -1, segment = -1;
    while (j < recs.size() && recs[j].lo == recs[i].lo && recs[j].hi == recs[i].hi) {
      sum += recs[j].weight;
      if (recs[j].source >= 0)
        edge = recs[j].source;
      else
        segment = -1 - recs[j].source;
      ++j;
    }
    if (sum != 0) {
      const std::string pair = "(" + std::to_string(recs[i].lo) + " " + std::to_string(recs[i].hi) + ")";
      std::string what;
      if (segment < 0)
        what = "boundary edge " + pair + " of triangle " + std::to_string(boundary_tri_[edge]) +
               " is not on the domain boundary";
      else if (edge < 0)
        what = "domain boundary piece " + pair + " of input segment " + std::to_string(segment) +
               " is not a boundary edge of the mesh";
      else
        what = "boundary edge " + pair + " of triangle " + std::to_string(boundary_tri_[edge]) +
               " runs against the domain boundary (input segment " + std::to_string(segment) +
               "): the mesh lies outside";
      sink_.add(CheckKind::BoundaryFace, {recs[i].lo, recs[i].hi}, what);
    }
    i = j;
  }
}

// No mesh vertex in the relative interior of an input segment: the interior
// vertices of every segment chain, and any boundary vertex that is not an
// input vertex (the boundary is the union of the loop segments).
void Checker2::check_steiner() {
  std::vector<char> flag(m_.vertices.size(), 0);
  for (std::size_t s = 0; s + 1 < chain_offset_.size(); ++s)
    for (int j = chain_offset_[s] + 1; j + 1 < chain_offset_[s + 1]; ++j) flag[chain_items_[j]] = 1;
  for (const auto& e : boundary_)
    for (int v : e)
      if (mesh2in_[v] < 0) flag[v] = 1;
  for (std::size_t v = 0; v < flag.size(); ++v)
    if (flag[v])
      sink_.add(CheckKind::SteinerOnBoundary, {static_cast<std::int64_t>(v)},
                "mesh vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) +
                    " lies in the relative interior of an input segment");
}

void Checker2::check_located(const Domain2& d) {
  if (d.loops.empty()) {
    sink_.note("vertex location skipped: the domain has no loops (not built by make_domain?)");
    return;
  }
  // Vertices of the segment chains are on the boundary by stage 4 (a rounded
  // Steiner point may lie an ulp outside; near_segment accepted it).
  std::vector<char> on_chain(m_.vertices.size(), 0);
  for (const int v : chain_items_) on_chain[static_cast<std::size_t>(v)] = 1;
  const CellLocator locator(d, m_.vertices.size());
  for (std::size_t v = 0; v < m_.vertices.size(); ++v)
    if (!on_chain[v] && locator.locate(m_.vertices[v]) == Location::Outside)
      sink_.add(CheckKind::VertexOutside, {static_cast<std::int64_t>(v)},
                "vertex " + std::to_string(v) + " at " + format_point(m_.vertices[v]) + " is outside the domain");
}

}  // namespace pqmesh::detail::check2d
