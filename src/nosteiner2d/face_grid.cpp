// Bucket grid of sides and vertices; see face_grid.hpp.
#include "nosteiner2d/face_grid.hpp"

#include <algorithm>
#include <cmath>

namespace pqmesh::detail {

FaceGrid::FaceGrid(const Domain2& domain) {
  const auto& P = domain.pslg.vertices;
  double total = 0;
  for (const auto& loop : domain.loops) {
    const int n = static_cast<int>(loop.size());
    for (int k = 0; k < n; ++k) {
      sides_.push_back({loop[k], loop[(k + 1) % n]});
      vertices_.push_back(loop[k]);
      total += norm(P[loop[(k + 1) % n]] - P[loop[k]]);
    }
  }
  lo_ = domain.bbox_min;
  const double w = domain.bbox_max.x - lo_.x, h = domain.bbox_max.y - lo_.y;
  // Cells about the mean side length, at most ~4 n cells.
  const double n = static_cast<double>(std::max<std::size_t>(1, sides_.size()));
  cell_ = std::max({total / n, std::sqrt(std::max(w * h, 1e-300) / (4 * n)), std::max(w, h) / 4096});
  if (!(cell_ > 0)) cell_ = 1;
  nx_ = std::max(1, static_cast<int>(std::ceil(w / cell_)) + 1);
  ny_ = std::max(1, static_cast<int>(std::ceil(h / cell_)) + 1);
  side_cells_.assign(static_cast<std::size_t>(nx_) * ny_, {});
  vertex_cells_.assign(static_cast<std::size_t>(nx_) * ny_, {});
  for (int s = 0; s < static_cast<int>(sides_.size()); ++s) {
    const Vec2 a = P[sides_[s][0]], b = P[sides_[s][1]];
    const auto c0 = cell_of({std::min(a.x, b.x), std::min(a.y, b.y)});
    const auto c1 = cell_of({std::max(a.x, b.x), std::max(a.y, b.y)});
    for (int i = c0[0]; i <= c1[0]; ++i)
      for (int j = c0[1]; j <= c1[1]; ++j) side_cells_[static_cast<std::size_t>(j) * nx_ + i].push_back(s);
  }
  for (int v = 0; v < static_cast<int>(vertices_.size()); ++v) {
    const auto c = cell_of(P[vertices_[v]]);
    vertex_cells_[static_cast<std::size_t>(c[1]) * nx_ + c[0]].push_back(v);
  }
  stamp_side_.assign(sides_.size(), 0);
  stamp_vertex_.assign(vertices_.size(), 0);
}

std::array<int, 2> FaceGrid::cell_of(Vec2 p) const {
  const double fx = std::floor((p.x - lo_.x) / cell_), fy = std::floor((p.y - lo_.y) / cell_);
  return {static_cast<int>(std::clamp(fx, 0.0, static_cast<double>(nx_ - 1))),
          static_cast<int>(std::clamp(fy, 0.0, static_cast<double>(ny_ - 1)))};
}

void FaceGrid::query(Vec2 c, double radius, std::vector<int>& side_ids, std::vector<int>& vertex_ids) const {
  side_ids.clear();
  vertex_ids.clear();
  if (++stamp_ == 0) {  // wrapped: reset the marks
    std::fill(stamp_side_.begin(), stamp_side_.end(), 0);
    std::fill(stamp_vertex_.begin(), stamp_vertex_.end(), 0);
    stamp_ = 1;
  }
  auto c0 = cell_of({c.x - radius, c.y - radius});
  auto c1 = cell_of({c.x + radius, c.y + radius});
  // One extra cell each way absorbs the rounding of the cell computation.
  const int i0 = std::max(0, c0[0] - 1), j0 = std::max(0, c0[1] - 1);
  const int i1 = std::min(nx_ - 1, c1[0] + 1), j1 = std::min(ny_ - 1, c1[1] + 1);
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const std::size_t cell = static_cast<std::size_t>(j) * nx_ + i;
      for (const int s : side_cells_[cell])
        if (stamp_side_[s] != stamp_) stamp_side_[s] = stamp_, side_ids.push_back(s);
      for (const int v : vertex_cells_[cell])
        if (stamp_vertex_[v] != stamp_) stamp_vertex_[v] = stamp_, vertex_ids.push_back(v);
    }
  std::sort(side_ids.begin(), side_ids.end());
  std::sort(vertex_ids.begin(), vertex_ids.end());
}

}  // namespace pqmesh::detail
