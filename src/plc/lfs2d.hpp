#pragma once
// Internals of the 2D local feature size (pqmesh/lfs.hpp): the feature model
// and the distance constructions shared by the brute-force and the grid
// evaluator, so that both compute bit-identical distances.
#include <array>
#include <vector>

#include "plc/lfs_distance.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// A feature of P: a vertex (b < 0, a = vertex id) or a closed edge (a, b).
struct LfsFeature {
  int a = -1, b = -1;
  bool is_vertex() const { return b < 0; }
};

// Combinatorial disjointness. In a valid Domain2 two features meet exactly
// when they share a vertex (loops are simple and pairwise disjoint, no vertex
// lies on a non-incident edge), so this is decided from ids alone.
inline bool lfs_disjoint(const LfsFeature& f, const LfsFeature& g) {
  const bool shares = f.a == g.a || (g.b >= 0 && f.a == g.b) || (f.b >= 0 && (f.b == g.a || f.b == g.b));
  return !shares;
}

inline double lfs_dist2(Vec2 x, const LfsFeature& f, const std::vector<Vec2>& points) {
  return f.is_vertex() ? lfs_dist2_point(x, points[f.a]) : lfs_dist2_segment(x, points[f.a], points[f.b]);
}

// Every feature of the domain: the vertices on its loops (in loop order),
// then its edges (loop by loop, in loop order).
std::vector<LfsFeature> lfs_features(const Domain2& domain);

// The boundary tests of lfs_integral, accelerated by a uniform n x n bucket
// grid (n ~ sqrt(edges)) over the bounding square; every edge is listed in
// every bucket of its bounding-box range (inflated by a tiny margin, so the
// listing is conservative). The grid only prunes; decisions are exact
// (orient2d and coordinate comparisons). Not thread-safe (visit stamps).
class BoundaryBuckets2 {
 public:
  explicit BoundaryBuckets2(const Domain2& domain);  // keeps a reference
  // Does dP meet the closed box [p, q]?
  bool box_meets_boundary(Vec2 p, Vec2 q);
  // The same answer as locate(domain, s), in time ~ the edges of s's row.
  Location where(Vec2 s);

 private:
  int gi(double v, double l) const;
  const Domain2& domain_;
  std::vector<std::array<int, 2>> edges_;  // loop edges (vertex ids)
  Vec2 glo_{};
  double gw_ = 1, margin_ = 0;
  int gn_ = 1;
  std::vector<std::vector<int>> bucket_;
  std::vector<int> stamp_;
  int stamp_id_ = 0;
};

}  // namespace pqmesh::detail
