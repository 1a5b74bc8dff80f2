#pragma once
// Pieces shared by the 2D and 3D validity checkers (check2d*.cpp, check3d*.cpp):
// formatting, issue collection, and the checks whose logic is the same in both.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geometry/large_page_allocator.hpp"
#include "mesh/radix_sort.hpp"
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
  std::vector<int, LargePageAllocator<int>> items;  // two per edge: a big table filled all over
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

// The order of sort_by_coordinates by comparisons (the reference; used when a
// coordinate is NaN, where ordered_key has no meaning).
template <class V>
std::vector<int> sort_by_coordinates_compared(const std::vector<V>& points) {
  std::vector<int> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (coord_less(points[a], points[b])) return true;
    if (coord_less(points[b], points[a])) return false;
    return a < b;
  });
  return order;
}

// Ties (equal coordinates; -0.0 == +0.0) by id. The coordinates' ordered
// keys (mesh/radix_sort.hpp) and the id are copied next to each other and
// sorted as integer tuples: the same order as the comparison above, without
// reading the points from the comparator. (Measured on plate_holes, 287,615
// vertices: fewer instructions than both the indirect comparison sort and
// three stable radix passes.)
template <class V>
std::vector<int> sort_by_coordinates(const std::vector<V>& points) {
  for (const V& p : points) {
    bool nan = p.x != p.x || p.y != p.y;
    if constexpr (requires { p.z; }) nan = nan || p.z != p.z;
    if (nan) return sort_by_coordinates_compared(points);
  }
  struct Item {
    std::uint64_t x, y, z;
    int id;
  };
  std::vector<Item> items(points.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    const V& p = points[i];
    std::uint64_t z = 0;
    if constexpr (requires { p.z; }) z = ordered_key(p.z);
    items[i] = {ordered_key(p.x), ordered_key(p.y), z, static_cast<int>(i)};
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    if (a.z != b.z) return a.z < b.z;
    return a.id < b.id;
  });
  std::vector<int> order(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) order[i] = items[i].id;
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

// ---- checks shared by both dimensions (same logic, same messages) ---------

// Stage 1: BadIndex when a marker array is neither empty nor one entry per item.
void check_marker_count(IssueSink& sink, std::size_t markers, std::size_t items, const char* what);

// Stage 3: UnusedVertex for every vertex on no element ("triangle",
// "tetrahedron").
template <class V, class Element>
void report_unused_vertices(IssueSink& sink, const std::vector<V>& points, const std::vector<Element>& elements,
                            const char* element_name) {
  std::vector<char> used(points.size(), 0);
  for (const auto& q : elements)
    for (int v : q) used[v] = 1;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (!used[v])
      sink.add(CheckKind::UnusedVertex, {static_cast<std::int64_t>(v)},
               "vertex " + std::to_string(v) + " at " + format_point(points[v]) + " is on no " + element_name);
}

// Stage 3: NonConforming for every group of vertices with exactly the same
// coordinates (`order` from sort_by_coordinates). Such vertices cannot be told
// apart by geometry; elements using one or the other do not share faces.
template <class V>
void report_coincident_vertices(IssueSink& sink, const std::vector<V>& points, const std::vector<int>& order) {
  for (std::size_t i = 0; i + 1 < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && points[order[j]] == points[order[i]]) ++j;
    if (j - i > 1) {
      std::vector<std::int64_t> ids(order.begin() + static_cast<long>(i), order.begin() + static_cast<long>(j));
      std::vector<int> vs(order.begin() + static_cast<long>(i), order.begin() + static_cast<long>(j));
      sink.add(CheckKind::NonConforming, std::move(ids),
               "vertices " + format_ids(vs) + " have the same coordinates " + format_point(points[order[i]]));
    }
    i = j;
  }
}

// Stage 3: the vertices lying on one boundary element (edge / triangle) other
// than its corners, searched breadth-first from the corners along `adj`,
// expanding only through vertices w with on(w). found(w) is called once per
// vertex over all searches (`reported` remembers them). Returns false when the
// search stopped at kMaxHangingExpansion vertices.
inline constexpr std::size_t kMaxHangingExpansion = 1024;
template <class On, class Found>
bool search_hanging_vertices(const Adjacency& adj, std::span<const int> corners, std::vector<char>& reported,
                             std::vector<int>& queue, On on, Found found) {
  bool capped = false;
  queue.assign(corners.begin(), corners.end());
  for (std::size_t head = 0; head < queue.size(); ++head) {
    for (int w : adj.of(queue[head])) {
      if (std::find(queue.begin(), queue.end(), w) != queue.end()) continue;
      if (!on(w)) continue;
      if (queue.size() >= kMaxHangingExpansion) {
        capped = true;
        break;
      }
      queue.push_back(w);
      if (!reported[w]) {
        reported[w] = 1;
        found(w);
      }
    }
  }
  return !capped;
}

// Stage 4: in2mesh[i] = the mesh vertex at input vertex i's exact coordinates
// (or -1), mesh2in the inverse (or -1); MissingVertex for every referenced
// input vertex that is no mesh vertex. Returns the number of unreferenced
// input vertices (not required to be mesh vertices).
// find(i) gives the mesh vertex at input vertex i's coordinates, as
// find_vertex would (the overload below uses find_vertex itself).
template <class V, class Find>
int map_input_vertices_with(IssueSink& sink, std::size_t mesh_vertices, const std::vector<V>& input,
                            const std::vector<char>& referenced, std::vector<int>& in2mesh, std::vector<int>& mesh2in,
                            Find find) {
  in2mesh.assign(input.size(), -1);
  mesh2in.assign(mesh_vertices, -1);
  int unreferenced = 0;
  for (std::size_t i = 0; i < input.size(); ++i) {
    const int mv = find(i);
    in2mesh[i] = mv;
    if (mv >= 0) mesh2in[mv] = static_cast<int>(i);
    if (!referenced[i]) {
      ++unreferenced;
      continue;
    }
    if (mv < 0)
      sink.add(CheckKind::MissingVertex, {static_cast<std::int64_t>(i)},
               "input vertex " + std::to_string(i) + " at " + format_point(input[i]) + " is not a mesh vertex");
  }
  return unreferenced;
}
template <class V>
int map_input_vertices_by_coordinates(IssueSink& sink, const std::vector<V>& mesh_points,
                                      const std::vector<int>& order,
                                      const std::vector<V>& input, const std::vector<char>& referenced,
                                      std::vector<int>& in2mesh, std::vector<int>& mesh2in) {
  return map_input_vertices_with(sink, mesh_points.size(), input, referenced, in2mesh, mesh2in,
                                 [&](std::size_t i) { return find_vertex(mesh_points, order, input[i]); });
}

// Stage 4: the walk of an input edge (segment) from mesh vertex a to mesh
// vertex b, each step to the unique neighbour w of the current vertex c (in
// `adj`) with step(c, w): w lies on the edge strictly closer to b.
struct ChainWalk {
  enum class End { Reached, Stuck, Forked };
  End end = End::Reached;
  std::vector<int> chain;  // a, ..., the last vertex reached
  int next = -1, other = -1;  // Forked: two qualifying neighbours of chain.back()
};
template <class Step>
ChainWalk walk_chain(const Adjacency& adj, int a, int b, Step step) {
  ChainWalk walk;
  walk.chain.push_back(a);
  int c = a;
  while (c != b) {
    int next = -1, found = 0, other = -1;
    for (int w : adj.of(c)) {
      if (!(w == b || step(c, w))) continue;
      if (found++ == 0)
        next = w;
      else
        other = w;
    }
    if (found == 0) {
      walk.end = ChainWalk::End::Stuck;
      return walk;
    }
    if (found > 1) {
      walk.end = ChainWalk::End::Forked;
      walk.next = next;
      walk.other = other;
      return walk;
    }
    walk.chain.push_back(next);
    c = next;
  }
  return walk;
}

// The public entry points of both dimensions: a Checker (Checker2 / Checker3)
// fills one report; the domain stages run after stages 1-3, told whether those
// were clean.
template <class Checker, class Mesh>
CheckReport run_topology_check(const Mesh& mesh, const CheckOptions& options) {
  CheckReport report;
  Checker checker(mesh, options, report);
  checker.run_topology();
  return report;
}
template <class Checker, class Mesh, class Domain>
CheckReport run_full_check(const Mesh& mesh, const Domain& domain, const CheckOptions& options) {
  CheckReport report;
  Checker checker(mesh, options, report);
  const bool ok = checker.run_topology();
  checker.run_domain(domain, ok);
  return report;
}

// Volume issue when the measured total volume (area: quantity "area") differs
// from the domain's beyond the relative tolerance.
void compare_volume(IssueSink& sink, const char* quantity, double mesh_volume, double domain_volume,
                    double tolerance);

}  // namespace pqmesh::detail
