// Insertion order guard for the Delaunay phase (see insertion_order.hpp).
#include "cdt2d/insertion_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace pqmesh::cdt2d::detail {
namespace {

std::uint64_t spread_bits(std::uint64_t v) {
  v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
  v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
  v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
  v = (v | (v << 2)) & 0x3333333333333333ull;
  v = (v | (v << 1)) & 0x5555555555555555ull;
  return v;
}

}  // namespace

std::vector<int> insertion_order(const std::vector<Vec2>& pts) {
  const std::size_t n = pts.size();
  if (n < 1024) return {};
  Vec2 lo = pts[0], hi = pts[0];
  double tour = 0;
  for (std::size_t i = 0; i < n; ++i) {
    lo = {std::min(lo.x, pts[i].x), std::min(lo.y, pts[i].y)};
    hi = {std::max(hi.x, pts[i].x), std::max(hi.y, pts[i].y)};
    if (i > 0) tour += std::abs(pts[i].x - pts[i - 1].x) + std::abs(pts[i].y - pts[i - 1].y);
  }
  const double side = std::max(hi.x - lo.x, hi.y - lo.y);
  // A space-filling-curve order of n points in a square of this side has a
  // tour of a few side * sqrt(n); an incoherent order is about n * side / 2.
  if (!(tour > 32.0 * side * std::sqrt(static_cast<double>(n)))) return {};
  auto quantize = [](double v, double a, double w) {
    const double t = w > 0 ? (v - a) / w : 0.0;
    return static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * 4294967295.0);
  };
  std::vector<std::pair<std::uint64_t, int>> keyed(n);
  for (std::size_t i = 0; i < n; ++i)
    keyed[i] = {spread_bits(quantize(pts[i].x, lo.x, side)) | (spread_bits(quantize(pts[i].y, lo.y, side)) << 1),
                static_cast<int>(i)};
  std::sort(keyed.begin(), keyed.end());  // ties broken by index: deterministic
  std::vector<int> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace pqmesh::cdt2d::detail
