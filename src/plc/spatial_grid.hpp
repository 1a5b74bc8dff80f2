#pragma once
// A uniform grid over the bounding boxes of triangles (DESIGN.md §8: flat
// arrays). A triangle is listed in every cell its bounding box overlaps.
// Cell indices are monotone functions of the coordinates (floating-point
// subtraction and multiplication by a positive constant are monotone), so two
// triangles whose boxes overlap always share a cell: the grid only prunes,
// every decision is still made by exact predicates.
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

  // f(i, j), i < j, once for every pair of triangles whose boxes overlap.
  // Order: by cell, then by position in the cell (deterministic).
  template <class F>
  void for_each_overlapping_pair(F&& f) const;

  // f(t) once for every triangle whose box contains p.
  template <class F>
  void for_each_containing(Vec3 p, F&& f) const;

  // f(t) once for every triangle whose box meets the ray from p towards +x
  // (box y- and z-ranges contain p.y, p.z and box hi.x >= p.x).
  template <class F>
  void for_each_on_x_ray(Vec3 p, F&& f) const;

 private:
  int cell_index(double v, int axis) const;
  int flat(int i, int j, int k) const { return (k * n_[1] + j) * n_[0] + i; }

  Box3 bounds_{};
  std::array<double, 3> scale_{0, 0, 0};  // cells per unit length
  std::array<int, 3> n_{0, 0, 0};
  std::vector<Box3> boxes_;
  std::vector<std::array<int, 6>> range_;  // per triangle: lo i, j, k; hi i, j, k
  std::vector<int> start_;                 // CSR: cell -> items_[start_[c] .. start_[c+1])
  std::vector<int> items_;
};

template <class F>
void TriangleGrid::for_each_overlapping_pair(F&& f) const {
  const int cells = n_[0] * n_[1] * n_[2];
  for (int c = 0; c < cells; ++c) {
    const int ci = c % n_[0], cj = (c / n_[0]) % n_[1], ck = c / (n_[0] * n_[1]);
    for (int x = start_[c]; x < start_[c + 1]; ++x) {
      const int s = items_[x];
      const auto& rs = range_[s];
      for (int y = x + 1; y < start_[c + 1]; ++y) {
        const int t = items_[y];
        const auto& rt = range_[t];
        // Report the pair only in the lowest cell both ranges share.
        if (std::max(rs[0], rt[0]) != ci || std::max(rs[1], rt[1]) != cj || std::max(rs[2], rt[2]) != ck) continue;
        if (!boxes_[s].overlaps(boxes_[t])) continue;
        if (s < t)
          f(s, t);
        else
          f(t, s);
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
  for (int i = i0; i < n_[0]; ++i) {
    const int c = flat(i, j, k);
    for (int x = start_[c]; x < start_[c + 1]; ++x) {
      const int t = items_[x];
      if (std::max(i0, range_[t][0]) != i) continue;  // visit each triangle once along the row
      const Box3& b = boxes_[t];
      if (b.hi.x < p.x || b.lo.y > p.y || b.hi.y < p.y || b.lo.z > p.z || b.hi.z < p.z) continue;
      f(t);
    }
  }
}

}  // namespace pqmesh::detail
