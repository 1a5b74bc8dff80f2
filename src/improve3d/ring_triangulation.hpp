#pragma once
// The best triangulation of a small polygon by the least score of its
// triangles: the optimisation inside edge removal (flips.hpp; Shewchuk,
// "Two discrete optimization algorithms for the topological improvement of
// tetrahedral meshes", 2002, after Klincsek's dynamic program, 1980).
//
// The polygon has vertices 0 .. m-1 in order (sides (i, i+1) and (m-1, 0)).
// A triangulation is a set of m-2 triangles (i, k, j), i < k < j, tiling it;
// its value is the least score of its triangles. The program finds the
// largest value: best(i, j) over the sub-polygon i .. j is the largest, over
// k in (i, j), of min(best(i, k), best(k, j), score(i, k, j)), with best(i,
// i+1) = +infinity. Ties go to the smallest k, so the result depends only on
// the scores. Cost: O(m^3) for m <= kMaxRingVertices.
#include <array>
#include <vector>

namespace pqmesh::improve3d::detail {

inline constexpr int kMaxRingVertices = 8;

class RingScores {
 public:
  explicit RingScores(int m) : m_(m) {}
  int size() const { return m_; }
  // A forbidden triangle has score -infinity (NaN is not allowed).
  void set(int i, int k, int j, double score) { score_[i][k][j] = score; }
  double at(int i, int k, int j) const { return score_[i][k][j]; }

 private:
  int m_;
  double score_[kMaxRingVertices][kMaxRingVertices][kMaxRingVertices] = {};
};

// Fills triangles with the best triangulation and returns its value, or
// returns -infinity (triangles then undefined) when every triangulation uses
// a forbidden triangle. 3 <= scores.size() <= kMaxRingVertices.
double best_ring_triangulation(const RingScores& scores, std::vector<std::array<int, 3>>& triangles);

}  // namespace pqmesh::improve3d::detail
