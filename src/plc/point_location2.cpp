#include "plc/point_location2.hpp"

#include <algorithm>
#include <cmath>

#include "plc/polygon2d.hpp"

namespace pqmesh::detail {

DomainLocator2::DomainLocator2(const Domain2& domain) : domain_(domain) {
  std::size_t n = 0;
  for (const auto& loop : domain.loops) n += loop.size();
  y0_ = domain.bbox_min.y;
  const double span = domain.bbox_max.y - domain.bbox_min.y;
  bands_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
  band_height_ = span > 0 ? span / bands_ : 1;
  const auto& P = domain.pslg.vertices;
  std::vector<std::array<int, 3>> listed;  // band, a, b
  for (const auto& loop : domain.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      const double ylo = std::min(P[static_cast<std::size_t>(a)].y, P[static_cast<std::size_t>(b)].y);
      const double yhi = std::max(P[static_cast<std::size_t>(a)].y, P[static_cast<std::size_t>(b)].y);
      for (int q = band(ylo); q <= band(yhi); ++q) listed.push_back({q, a, b});
    }
  std::sort(listed.begin(), listed.end());
  offsets_.assign(static_cast<std::size_t>(bands_) + 1, 0);
  for (const auto& e : listed) ++offsets_[static_cast<std::size_t>(e[0]) + 1];
  for (int q = 0; q < bands_; ++q) offsets_[static_cast<std::size_t>(q) + 1] += offsets_[static_cast<std::size_t>(q)];
  for (const auto& e : listed) edges_.push_back({e[1], e[2]});
}

int DomainLocator2::band(double y) const {
  const double t = std::floor((y - y0_) / band_height_);
  if (!(t >= 0)) return 0;
  return t >= bands_ - 1 ? bands_ - 1 : static_cast<int>(t);
}

Location DomainLocator2::locate(Vec2 p) const {
  const Domain2& d = domain_;
  if (d.loops.empty() || p.x < d.bbox_min.x || p.x > d.bbox_max.x || p.y < d.bbox_min.y || p.y > d.bbox_max.y)
    return Location::Outside;
  const auto& P = d.pslg.vertices;
  const int q = band(p.y);
  bool inside = false;
  for (int i = offsets_[static_cast<std::size_t>(q)]; i < offsets_[static_cast<std::size_t>(q) + 1]; ++i) {
    const Vec2 u = P[static_cast<std::size_t>(edges_[static_cast<std::size_t>(i)][0])];
    const Vec2 w = P[static_cast<std::size_t>(edges_[static_cast<std::size_t>(i)][1])];
    if (on_segment(p, u, w)) return Location::Boundary;
    if (ray_crosses_edge(p, u, w)) inside = !inside;
  }
  return inside ? Location::Inside : Location::Outside;
}

}  // namespace pqmesh::detail
