#include "plc/spatial_grid.hpp"

#include <algorithm>
#include <cmath>

namespace pqmesh::detail {

namespace {

double abs1(Vec3 v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }
double max_abs(Vec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Conservative separating-axis test (Akenine-Möller's 13 axes minus the three
// box normals, which the bounding-box range already covers): false only when
// the triangle abc is clearly apart from the box (center, half extents), by
// more than a slack that dwarfs the rounding of these double computations.
bool may_touch(Vec3 a, Vec3 b, Vec3 c, Vec3 center, Vec3 half) {
  const Vec3 v[3] = {a - center, b - center, c - center};
  const double size = std::max({max_abs(v[0]), max_abs(v[1]), max_abs(v[2])}) + max_abs(half);
  auto separated = [&](Vec3 axis) {
    const double p0 = dot(axis, v[0]), p1 = dot(axis, v[1]), p2 = dot(axis, v[2]);
    const double r = half.x * std::abs(axis.x) + half.y * std::abs(axis.y) + half.z * std::abs(axis.z);
    const double slack = 1e-9 * abs1(axis) * size;
    return std::min({p0, p1, p2}) > r + slack || std::max({p0, p1, p2}) < -r - slack;
  };
  if (separated(cross(v[1] - v[0], v[2] - v[0]))) return false;
  const Vec3 units[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int e = 0; e < 3; ++e) {
    const Vec3 edge = v[(e + 1) % 3] - v[e];
    for (const Vec3& u : units)
      if (separated(cross(edge, u))) return false;
  }
  return true;
}

}  // namespace

int TriangleGrid::cell_index(double v, int axis) const {
  const double lo = axis_coord(bounds_.lo, axis);
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
  std::array<double, 3> cell_size{};
  for (int a = 0; a < 3; ++a) {
    n_[a] = static_cast<int>(std::min(1024.0, std::floor(ext[a] / h) + 1));
    scale_[a] = ext[a] > 0 ? n_[a] / ext[a] : 0;
    cell_size[a] = ext[a] > 0 ? ext[a] / n_[a] : 0;
  }
  // Margin covering the rounding of cell_index (relative to the coordinates)
  // with a wide safety factor.
  const double magnitude = std::max(max_abs(bounds_.lo), max_abs(bounds_.hi));
  const std::array<double, 3> margin{1e-6 * cell_size[0] + 1e-12 * magnitude, 1e-6 * cell_size[1] + 1e-12 * magnitude,
                                     1e-6 * cell_size[2] + 1e-12 * magnitude};
  const int cells = n_[0] * n_[1] * n_[2];
  tri_start_.assign(nt + 1, 0);
  for (int t = 0; t < nt; ++t) {
    const Box3& b = boxes_[t];
    const int r[6] = {cell_index(b.lo.x, 0), cell_index(b.lo.y, 1), cell_index(b.lo.z, 2),
                      cell_index(b.hi.x, 0), cell_index(b.hi.y, 1), cell_index(b.hi.z, 2)};
    const bool single = r[0] == r[3] && r[1] == r[4] && r[2] == r[5];
    const Vec3 a = vertices[triangles[t][0]], bb = vertices[triangles[t][1]], c = vertices[triangles[t][2]];
    for (int k = r[2]; k <= r[5]; ++k)
      for (int j = r[1]; j <= r[4]; ++j)
        for (int i = r[0]; i <= r[3]; ++i) {
          if (!single) {
            const Vec3 center{bounds_.lo.x + (i + 0.5) * cell_size[0], bounds_.lo.y + (j + 0.5) * cell_size[1],
                              bounds_.lo.z + (k + 0.5) * cell_size[2]};
            const Vec3 half{0.5 * cell_size[0] + margin[0], 0.5 * cell_size[1] + margin[1],
                            0.5 * cell_size[2] + margin[2]};
            if (!may_touch(a, bb, c, center, half)) continue;
          }
          tri_cells_.push_back(flat(i, j, k));
        }
    tri_start_[t + 1] = static_cast<int>(tri_cells_.size());
  }
  std::vector<int> count(cells + 1, 0);
  for (int c : tri_cells_) ++count[c + 1];
  for (int c = 0; c < cells; ++c) count[c + 1] += count[c];
  start_ = count;
  items_.resize(tri_cells_.size());
  for (int t = 0; t < nt; ++t)
    for (int x = tri_start_[t]; x < tri_start_[t + 1]; ++x) items_[count[tri_cells_[x]]++] = t;
}

}  // namespace pqmesh::detail
