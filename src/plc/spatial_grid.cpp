#include "plc/spatial_grid.hpp"

#include <algorithm>
#include <cmath>

namespace pqmesh::detail {

int TriangleGrid::cell_index(double v, int axis) const {
  const double lo = axis == 0 ? bounds_.lo.x : (axis == 1 ? bounds_.lo.y : bounds_.lo.z);
  const double c = (v - lo) * scale_[axis];
  if (!(c > 0)) return 0;
  if (c >= n_[axis] - 1) return n_[axis] - 1;
  return static_cast<int>(c);
}

TriangleGrid::TriangleGrid(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles,
                           double per_cell) {
  const int nt = static_cast<int>(triangles.size());
  boxes_.resize(nt);
  for (int t = 0; t < nt; ++t) {
    const Vec3 a = vertices[triangles[t][0]], b = vertices[triangles[t][1]], c = vertices[triangles[t][2]];
    boxes_[t].lo = {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
    boxes_[t].hi = {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
    if (t == 0) bounds_ = boxes_[0];
    bounds_.lo = {std::min(bounds_.lo.x, boxes_[t].lo.x), std::min(bounds_.lo.y, boxes_[t].lo.y),
                  std::min(bounds_.lo.z, boxes_[t].lo.z)};
    bounds_.hi = {std::max(bounds_.hi.x, boxes_[t].hi.x), std::max(bounds_.hi.y, boxes_[t].hi.y),
                  std::max(bounds_.hi.z, boxes_[t].hi.z)};
  }
  // Cell size: cubes of volume (box volume * per_cell / triangles), so about
  // per_cell triangles per cell; flat boxes get a thin layer of cells. The
  // count per axis is capped, and the total stays within a few times the
  // number of triangles.
  const std::array<double, 3> ext{bounds_.hi.x - bounds_.lo.x, bounds_.hi.y - bounds_.lo.y,
                                  bounds_.hi.z - bounds_.lo.z};
  const double target = std::max(1.0, nt / per_cell);
  const double longest = std::max({ext[0], ext[1], ext[2]});
  double h = std::cbrt(ext[0] * ext[1] * ext[2] / target);
  if (!(h > 0)) h = longest / std::sqrt(target);
  if (!(h > 0)) h = 1;
  for (int attempt = 0; attempt < 64; ++attempt) {
    double total = 1;
    for (int a = 0; a < 3; ++a) total *= std::min(1024.0, std::floor(ext[a] / h) + 1);
    if (total <= 4 * target + 64) break;
    h *= 1.25;
  }
  for (int a = 0; a < 3; ++a) {
    n_[a] = static_cast<int>(std::min(1024.0, std::floor(ext[a] / h) + 1));
    scale_[a] = ext[a] > 0 ? n_[a] / ext[a] : 0;
  }
  range_.resize(nt);
  const int cells = n_[0] * n_[1] * n_[2];
  std::vector<int> count(cells + 1, 0);
  for (int t = 0; t < nt; ++t) {
    const Box3& b = boxes_[t];
    range_[t] = {cell_index(b.lo.x, 0), cell_index(b.lo.y, 1), cell_index(b.lo.z, 2),
                 cell_index(b.hi.x, 0), cell_index(b.hi.y, 1), cell_index(b.hi.z, 2)};
    const auto& r = range_[t];
    for (int k = r[2]; k <= r[5]; ++k)
      for (int j = r[1]; j <= r[4]; ++j)
        for (int i = r[0]; i <= r[3]; ++i) ++count[flat(i, j, k) + 1];
  }
  for (int c = 0; c < cells; ++c) count[c + 1] += count[c];
  start_ = count;
  items_.resize(start_[cells]);
  for (int t = 0; t < nt; ++t) {
    const auto& r = range_[t];
    for (int k = r[2]; k <= r[5]; ++k)
      for (int j = r[1]; j <= r[4]; ++j)
        for (int i = r[0]; i <= r[3]; ++i) items_[count[flat(i, j, k)]++] = t;
  }
}

}  // namespace pqmesh::detail
