#pragma once
// The state of one Delaunay refinement run (internal; the algorithm is
// described in refine.hpp). refine.cpp: the main loop, walk, cavity and
// splits; refine_setup.cpp: subsegment origins, sharp input vertices and the
// output chains.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <queue>
#include <vector>

#include "cdt2d/refine.hpp"
#include "cdt2d/triangulation.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::cdt2d::detail {

inline constexpr double kMinPieceFraction = 0x1p-24;  // never split below |AB| / 2^24

inline std::uint64_t pair_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

struct QueuedTri {
  int t;
  int v[3];
};

// Result of the walk towards a new point.
struct Walk {
  enum class End { Triangle, Edge, Vertex, Constraint, Failed } end = End::Failed;
  int t = -1;  // Triangle / Edge / Vertex / Constraint: the triangle where the walk ended
  int h = -1;  // Edge: half-edge of t holding the point; Constraint: the constrained half-edge met
};

class Refiner {
 public:
  Refiner(const CdtInput& in, const RefineOptions& opt, const SegmentSupport& sup, std::vector<Vec2>& pts,
          Triangulation& tri, std::vector<std::size_t> piece_begin)
      : in_(in), sup_(sup), pts_(pts), tri_(tri), piece_begin_(std::move(piece_begin)), n_in_(static_cast<int>(pts.size())) {
    // pts holds exactly the input points here (in.points may have been moved
    // into it); only in.constraints is read later.
    cap_ = opt.max_new_points != 0 ? opt.max_new_points : 2 * pts.size();
    split_ = opt.split_constraints;
    const double th = opt.min_angle_degrees * std::numbers::pi / 180.0;
    cos_target_ = std::cos(th);
    off_factor_ = opt.off_centers ? 0.475 / std::tan(th / 2) : std::numeric_limits<double>::infinity();
    seg_of_.reserve(pts_.capacity());  // grows with pts_, within its reserve (refine.cpp)
    seg_of_.assign(pts_.size(), -1);
    build_piece_origins();
    build_sharp_vertices();
  }

  void run(RefineResult& out);

 private:
  void build_piece_origins();
  int group_of(int k) const {
    return sup_.constraint_segment.empty() ? k : sup_.constraint_segment[static_cast<std::size_t>(k)];
  }
  std::array<Vec2, 2> ends_of(int k) const {
    if (sup_.constraint_segment.empty()) {
      const auto [a, b] = in_.constraints[static_cast<std::size_t>(k)];
      return {pts_[static_cast<std::size_t>(a)], pts_[static_cast<std::size_t>(b)]};
    }
    return sup_.segment_ends[static_cast<std::size_t>(group_of(k))];
  }
  void build_sharp_vertices();
  int origin_of(int u, int v) const;
  bool is_bad(int t) const;       // inside, real, and small_angle
  bool small_angle(int t) const;  // smallest angle below the target (any real triangle)
  bool is_excused(int t) const;
  int shortest_edge(int t) const;
  Vec2 new_point_for(int t) const;
  Walk walk_to(int t, Vec2 c);
  bool collect_encroached(const Walk& w, Vec2 c);
  void insert_interior(Vec2 c, const Walk& w);
  // split_ off (refine_inside.cpp; refine.hpp "Without constraint splits"):
  void refine_inside(const QueuedTri& q, Vec2 c, const Walk& w);
  bool too_near_cavity(double l2, Vec2 c) const;
  double shortest2(int t) const;
  double length2_of(int h) const {
    const auto& T = tri_.tri(tri_of(h));
    const Vec2 d = pts_[T.v[prev3(edge_of(h))]] - pts_[T.v[next3(edge_of(h))]];
    return dot(d, d);
  }
  int flat_constrained_edge(Vec2 c, int except) const;
  Vec2 apex_of(int h, double tan_beta) const;
  bool try_point(const QueuedTri& q, int from, Vec2 p, double near2, int except);
  bool splittable(int u, int v) const;
  bool split_subsegment(int u, int v);
  void after_insertion(int p);
  std::pair<double, double> smallest_angle_terms(int t) const;
  double cos_smallest(int t) const;
  // Queues a bad triangle: recorded in bad_ (the final check visits every
  // queued slot) and ordered in worst_ by its smallest angle, smallest first,
  // ties to the first queued.
  void push_tri(int t) {
    const auto& T = tri_.tri(t);
    requeue({t, {T.v[0], T.v[1], T.v[2]}});
  }
  void requeue(const QueuedTri& q) {
    worst_.push({cos_smallest(q.t), -static_cast<std::int64_t>(bad_.size())});
    bad_.push_back(q);
  }
  bool still_there(const QueuedTri& q) const {
    if (q.t >= tri_.triangle_count()) return false;
    const auto& T = tri_.tri(q.t);
    return T.v[0] == q.v[0] && T.v[1] == q.v[1] && T.v[2] == q.v[2];
  }
  bool encroaches(int x, int u, int v) const {
    return x != kGhost && dot_sign(pts_[x], pts_[u], pts_[v]) != Sign::Positive;
  }
  void output(RefineResult& out);  // last: releases the refiner's and the triangulation's maps

  const CdtInput& in_;
  const SegmentSupport& sup_;
  std::vector<Vec2>& pts_;
  Triangulation& tri_;
  std::vector<std::size_t> piece_begin_;  // pieces_ of input constraint i: [piece_begin_[i], piece_begin_[i + 1])
  int n_in_;
  std::size_t cap_ = 0;
  bool split_ = true;  // RefineOptions::split_constraints
  double cos_target_ = 1;
  double off_factor_ = 0;
  std::vector<int> seg_of_;  // per vertex: input constraint (canonical) of a Steiner point on it, else -1
  std::vector<std::pair<std::uint64_t, int>> piece_origin_;  // initial pieces by undirected key
  std::vector<int> piece_canon_;                            // per initial piece: canonical origin
  std::vector<int> vgroup_;                                 // per vertex: the segment it lies on inside, or -1
  std::vector<std::uint8_t> sharp_;                         // per input vertex
  std::vector<std::uint64_t> sharp_pairs_;                  // pair_key of segments meeting in a sharp wedge
  std::vector<QueuedTri> bad_;
  std::priority_queue<std::pair<double, std::int64_t>> worst_;  // (cos of the smallest angle, -index in bad_)
  std::vector<std::array<int, 2>> segq_;
  std::size_t seg_head_ = 0;
  std::vector<int> stamp_;  // per triangle slot: the large cavity that last visited it (collect_encroached)
  int stamp_now_ = 0;
  std::vector<int> cavity_;
  std::vector<std::array<int, 2>> encroached_;
  std::size_t inserted_ = 0, on_constraints_ = 0, refused_ = 0;
  std::size_t given_up_outside_ = 0, given_up_near_ = 0, given_up_flat_ = 0, apex_points_ = 0, halfway_points_ = 0;  // split_ off (RefineResult)
  // Subsegments whose split was refused (rounding or orientation): never
  // tried again, so a bad triangle that encroaches only such subsegments is
  // given up instead of being re-queued forever. Rare path.
  std::unordered_set<std::uint64_t> refused_set_;
};


}  // namespace pqmesh::cdt2d::detail
