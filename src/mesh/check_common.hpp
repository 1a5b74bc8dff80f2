#pragma once
// Pieces shared by the 2D and 3D validity checkers (check2d.cpp, check3d.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// Collects issues into a report, counting all of them but storing at most
// `cap` per kind.
class IssueSink {
 public:
  IssueSink(CheckReport& report, std::size_t cap) : report_(report), cap_(cap) {}
  void add(CheckKind kind, std::vector<std::int64_t> ids, std::string message);
  std::int64_t count(CheckKind kind) const { return report_.count(kind); }
  void note(std::string text) { report_.notes.push_back(std::move(text)); }

 private:
  CheckReport& report_;
  std::size_t cap_;
  std::vector<std::size_t> stored_ = std::vector<std::size_t>(kCheckKindCount, 0);
};

// Compressed adjacency lists: the neighbours of v are items[offset[v] .. offset[v+1]).
struct Adjacency {
  std::vector<int> offset;
  std::vector<int> items;
  std::span<const int> of(int v) const {
    return {items.data() + offset[v], items.data() + offset[v + 1]};
  }
};

// Symmetric adjacency of n vertices from undirected edges (pairs may repeat;
// neighbour lists come out sorted and without repeats).
Adjacency make_adjacency(int n, const std::vector<std::array<int, 2>>& edges);

// Mesh vertex ids sorted by exact coordinates (lexicographic x, y[, z]).
template <class V>
bool coord_less(const V& a, const V& b) {
  if (a.x != b.x) return a.x < b.x;
  if constexpr (requires { a.z; }) {
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
  } else {
    return a.y < b.y;
  }
}

template <class V>
std::vector<int> sort_by_coordinates(const std::vector<V>& points) {
  std::vector<int> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (coord_less(points[a], points[b])) return true;
    if (coord_less(points[b], points[a])) return false;
    return a < b;
  });
  return order;
}

// The mesh vertex with exactly the coordinates of p, or -1 (the smallest id if
// several; duplicates are reported separately).
template <class V>
int find_vertex(const std::vector<V>& points, const std::vector<int>& order, const V& p) {
  auto it = std::lower_bound(order.begin(), order.end(), p,
                             [&](int v, const V& q) { return coord_less(points[v], q); });
  if (it == order.end() || coord_less(p, points[*it])) return -1;
  return *it;
}

std::string format_point(Vec2 p);
std::string format_point(Vec3 p);
std::string format_ids(std::span<const int> ids);
std::string format_number(double v);  // round-trip precision
std::string format_short(double v);   // 3 significant digits

// Neumaier's compensated summation (a measurement: keeps the rounding of a
// sum of many element volumes near one unit in the last place).
class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    if (std::abs(sum_) >= std::abs(x))
      c_ += (sum_ - t) + x;
    else
      c_ += (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + c_; }

 private:
  double sum_ = 0, c_ = 0;
};

// Relative difference |a - b| / max(|a|, |b|), 0 when both are 0.
double relative_difference(double a, double b);

}  // namespace pqmesh::detail
