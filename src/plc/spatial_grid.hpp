#pragma once
// A uniform grid over triangles (docs/DESIGN_RULES.md "Data layout and speed":
// flat arrays). A triangle is listed in every cell of its bounding-box range
// that it may touch: a separating-axis test (the 9 edge-cross-axis directions
// and the normal, evaluated in double with a generous slack, against the cell
// inflated by a margin) drops cells that are clearly apart, which keeps long
// diagonal slivers (fan triangulations of big facets) from filling whole
// rectangles. The filter is conservative: a point x of a triangle lies in the
// inflated box of the cell cell_index(x), so two triangles with a common point
// share that cell, a point on a triangle finds it in its own cell, and a ray
// along a row of cells finds every triangle it meets. Cell indices are monotone
// in the coordinates (floating-point subtraction and multiplication by a
// positive constant are monotone). The grid only prunes; every decision is made
// by exact predicates.
#include <algorithm>
#include <array>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

struct Box3 {
  Vec3 lo, hi;
  bool overlaps(const Box3& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y && lo.z <= o.hi.z && o.lo.z <= hi.z;
  }
  bool contains(Vec3 p) const {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
  }
};

class TriangleGrid {
 public:
  TriangleGrid() = default;
  // About `per_cell` triangles per cell on average (for well spread input).
  TriangleGrid(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles,
               double per_cell = 2.0);

  const Box3& box(int t) const { return boxes_[t]; }
  int size() const { return static_cast<int>(boxes_.size()); }

  // f(i, j), i < j, once for every pair of triangles whose boxes overlap and
  // whose groups differ. `group` (one per triangle) must be nondecreasing in
  // the triangle index (e.g. the owning facet, triangles listed facet by
  // facet), so a cell's list, sorted by index, holds each group contiguously
  // and pairs within a group cost nothing (a fan of thousands of slivers in
  // one facet would otherwise give millions of pairs).
  // Order: by cell, then by position in the cell (deterministic).
  template <class F>
  void for_each_overlapping_pair(const std::vector<int>& group, F&& f) const;

  // f(t) once for every triangle whose box contains p.
  template <class F>
  void for_each_containing(Vec3 p, F&& f) const;

  // f(t) once for every triangle whose box meets the ray from p towards +x
  // (box y- and z-ranges contain p.y, p.z and box hi.x >= p.x) and that is
  // listed in a cell of the ray's row; in increasing order of t.
  template <class F>
  void for_each_on_x_ray(Vec3 p, F&& f) const;

 private:
  int cell_index(double v, int axis) const;
  int flat(int i, int j, int k) const { return (k * n_[1] + j) * n_[0] + i; }

  Box3 bounds_{};
  std::array<double, 3> scale_{0, 0, 0};  // cells per unit length
  std::array<int, 3> n_{0, 0, 0};
  std::vector<Box3> boxes_;
  std::vector<int> start_;       // CSR: cell -> items_[start_[c] .. start_[c+1]), sorted by triangle
  std::vector<int> items_;
  std::vector<int> tri_start_;   // CSR: triangle -> tri_cells_[tri_start_[t] .. tri_start_[t+1])
  std::vector<int> tri_cells_;
};

template <class F>
void TriangleGrid::for_each_overlapping_pair(const std::vector<int>& group, F&& f) const {
  const int nt = size();
  std::vector<int> seen(nt, -1);  // seen[t] == s: pair (s, t) already reported
  for (int s = 0; s < nt; ++s) {
    for (int x = tri_start_[s]; x < tri_start_[s + 1]; ++x) {
      const int c = tri_cells_[x];
      const int end = start_[c + 1];
      // Items are sorted by triangle and groups are nondecreasing, so the
      // triangles after s in its own group come right after s.
      int y = static_cast<int>(std::upper_bound(items_.begin() + start_[c], items_.begin() + end, s) - items_.begin());
      while (y < end && group[items_[y]] == group[s]) ++y;
      for (; y < end; ++y) {
        const int t = items_[y];
        if (seen[t] == s) continue;
        seen[t] = s;
        if (boxes_[s].overlaps(boxes_[t])) f(s, t);
      }
    }
  }
}

template <class F>
void TriangleGrid::for_each_containing(Vec3 p, F&& f) const {
  if (boxes_.empty() || !bounds_.contains(p)) return;
  const int c = flat(cell_index(p.x, 0), cell_index(p.y, 1), cell_index(p.z, 2));
  for (int x = start_[c]; x < start_[c + 1]; ++x)
    if (boxes_[items_[x]].contains(p)) f(items_[x]);
}

template <class F>
void TriangleGrid::for_each_on_x_ray(Vec3 p, F&& f) const {
  if (boxes_.empty() || p.x > bounds_.hi.x || p.y < bounds_.lo.y || p.y > bounds_.hi.y || p.z < bounds_.lo.z ||
      p.z > bounds_.hi.z)
    return;
  const int i0 = cell_index(p.x, 0), j = cell_index(p.y, 1), k = cell_index(p.z, 2);
  std::vector<int> found;
  for (int i = i0; i < n_[0]; ++i) {
    const int c = flat(i, j, k);
    for (int x = start_[c]; x < start_[c + 1]; ++x) {
      const Box3& b = boxes_[items_[x]];
      if (b.hi.x < p.x || b.lo.y > p.y || b.hi.y < p.y || b.lo.z > p.z || b.hi.z < p.z) continue;
      found.push_back(items_[x]);
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  for (int t : found) f(t);
}

}  // namespace pqmesh::detail
