// Setup and output of a refinement run (refiner.hpp): which input
// constraint each subsegment comes from, which input vertices are sharp, and
// the constraint chains of the result.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "cdt2d/refiner.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::cdt2d::detail {

// Canonical origin of an initial piece: the smallest input constraint index
// among those having this piece (a side given in both directions).
void Refiner::build_piece_origins() {
  const auto& pieces = tri_.pieces();
  piece_origin_.reserve(pieces.size());
  for (std::size_t i = 0; i + 1 < piece_begin_.size(); ++i)
    for (std::size_t k = piece_begin_[i]; k < piece_begin_[i + 1]; ++k)
      piece_origin_.push_back({pair_key(pieces[k][0], pieces[k][1]), static_cast<int>(i)});
  std::sort(piece_origin_.begin(), piece_origin_.end());
  piece_origin_.erase(std::unique(piece_origin_.begin(), piece_origin_.end(),
                                  [](const auto& a, const auto& b) { return a.first == b.first; }),
                      piece_origin_.end());
  piece_canon_.resize(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) piece_canon_[k] = origin_of(pieces[k][0], pieces[k][1]);
}

// The subsegment u-v (a constrained edge): a Steiner end names its segment;
// otherwise it is an initial piece.
int Refiner::origin_of(int u, int v) const {
  if (seg_of_[static_cast<std::size_t>(u)] >= 0) return seg_of_[static_cast<std::size_t>(u)];
  if (seg_of_[static_cast<std::size_t>(v)] >= 0) return seg_of_[static_cast<std::size_t>(v)];
  const std::uint64_t key = pair_key(u, v);
  const auto it = std::lower_bound(piece_origin_.begin(), piece_origin_.end(), std::pair<std::uint64_t, int>{key, -1});
  if (it == piece_origin_.end() || it->first != key)
    throw InternalError("refine: constrained edge " + std::to_string(u) + "-" + std::to_string(v) + " has no origin");
  return it->second;
}

// Sharp input vertices: around each vertex the constraint directions sorted
// by angle; the wedge counter-clockwise after an outgoing constraint (domain
// on its left) is inside the domain. An inside wedge under 60 degrees makes
// the vertex sharp and its two segments a sharp pair. Angles are measured in
// double: this only classifies (which triangles are excused, where to split).
void Refiner::build_sharp_vertices() {
  sharp_.assign(static_cast<std::size_t>(n_in_), 0);
  vgroup_.reserve(pts_.capacity());  // grows with pts_
  vgroup_.assign(static_cast<std::size_t>(n_in_), -1);
  struct Dir {
    int v;
    double angle;
    int other;
    bool outgoing;
    int canon;
  };
  std::vector<Dir> dirs;
  const auto& pieces = tri_.pieces();
  for (std::size_t i = 0; i + 1 < piece_begin_.size(); ++i) {
    const std::size_t b = piece_begin_[i], e = piece_begin_[i + 1];
    if (b == e) continue;
    for (std::size_t k = b; k < e; ++k) {  // every piece end is an input vertex
      const int a = pieces[k][0], c = pieces[k][1];
      const Vec2 d = pts_[c] - pts_[a];
      dirs.push_back({a, std::atan2(d.y, d.x), c, true, piece_canon_[k]});
      dirs.push_back({c, std::atan2(-d.y, -d.x), a, false, piece_canon_[k]});
    }
  }
  std::sort(dirs.begin(), dirs.end(), [](const Dir& x, const Dir& y) {
    return x.v < y.v || (x.v == y.v && (x.angle < y.angle || (x.angle == y.angle && x.other < y.other)));
  });
  // Merge a side given in both directions (same neighbour).
  std::vector<Dir> merged;
  for (const Dir& d : dirs) {
    if (!merged.empty() && merged.back().v == d.v && merged.back().other == d.other) {
      merged.back().outgoing = merged.back().outgoing || d.outgoing;
      continue;
    }
    merged.push_back(d);
  }
  const double limit = std::numbers::pi / 3;
  for (std::size_t s = 0; s < merged.size();) {
    std::size_t e = s;
    while (e < merged.size() && merged[e].v == merged[s].v) ++e;
    // The vertex lies inside one segment when all its pieces belong to it.
    bool one = true;
    for (std::size_t k = s + 1; k < e; ++k) one = one && group_of(merged[k].canon) == group_of(merged[s].canon);
    if (one) vgroup_[static_cast<std::size_t>(merged[s].v)] = group_of(merged[s].canon);
    if (e - s >= 2) {
      for (std::size_t k = s; k < e; ++k) {
        const Dir& x = merged[k];
        const Dir& y = merged[k + 1 < e ? k + 1 : s];
        double w = y.angle - x.angle;
        if (k + 1 == e) w += 2 * std::numbers::pi;
        if (!x.outgoing || !(w > 0) || w >= limit) continue;
        sharp_[static_cast<std::size_t>(x.v)] = 1;
        if (group_of(x.canon) != group_of(y.canon)) sharp_pairs_.push_back(pair_key(group_of(x.canon), group_of(y.canon)));
      }
    }
    s = e;
  }
  std::sort(sharp_pairs_.begin(), sharp_pairs_.end());
}

// The result; the last use of the refiner. Constraints: per input
// constraint, per initial piece u -> v, the chain of constrained edges from u
// to v through Steiner points of the piece's canonical origin (at an input
// vertex in the middle of a constraint, the neighbour that lies towards v:
// dot_sign < 0). Then the triangles.
void Refiner::output(RefineResult& out) {
  const auto& pieces = tri_.pieces();
  for (std::size_t i = 0; i + 1 < piece_begin_.size(); ++i) {
    for (std::size_t k = piece_begin_[i]; k < piece_begin_[i + 1]; ++k) {
      const int u = pieces[k][0], v = pieces[k][1], canon = piece_canon_[k];
      int cur = u, prev = -1;
      for (int guard = 0; cur != v; ++guard) {
        if (guard > static_cast<int>(pts_.size())) throw InternalError("refine: constraint chain does not end");
        const int hv = tri_.half_edge(cur, v);
        if (hv >= 0 && tri_.constrained(hv)) {
          out.constraints.push_back({cur, v});
          out.constraint_origin.push_back(static_cast<int>(i));
          break;
        }
        int next = -1;
        const int t0 = tri_.vertex_triangle(cur);
        int t = t0;
        do {
          const int j = tri_.index_of(t, cur);
          const auto& T = tri_.tri(t);
          const int w = T.v[next3(j)];
          if (w != kGhost && w != prev && tri_.constrained(he(t, prev3(j))) &&
              seg_of_[static_cast<std::size_t>(w)] == canon &&
              (cur >= n_in_ || dot_sign(pts_[w], pts_[cur], pts_[v]) == Sign::Negative)) {
            next = w;
            break;
          }
          t = tri_of(T.n[next3(j)]);
        } while (t != t0);
        if (next < 0) throw InternalError("refine: constraint piece " + std::to_string(u) + "->" + std::to_string(v) + " lost");
        out.constraints.push_back({cur, next});
        out.constraint_origin.push_back(static_cast<int>(i));
        prev = cur;
        cur = next;
      }
    }
  }
  // Triangles: inside ones in slot order. The constraint bits, vertex map
  // and per-vertex tables are not needed any more: released first, so the
  // output array does not add to the peak memory on top of them.
  seg_of_ = {};
  vgroup_ = {};
  tri_.release_refinement_maps();
  // Inside triangles are never ghosts (refine_ops.cpp): the label decides,
  // the ghost test is a guard.
  std::size_t inside = 0;  // counted first: one allocation, no copies while growing
  for (int t = 0; t < tri_.triangle_count(); ++t) inside += tri_.inside(t);
  out.triangles.reserve(inside);
  for (int t = 0; t < tri_.triangle_count(); ++t) {
    if (!tri_.inside(t) || tri_.is_ghost(t)) continue;
    const auto& v = tri_.tri(t).v;
    out.triangles.push_back({v[0], v[1], v[2]});
  }
}

}  // namespace pqmesh::cdt2d::detail
