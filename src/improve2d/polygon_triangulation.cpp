// best_triangulation (polygon_triangulation.hpp).
#include "improve2d/polygon_triangulation.hpp"

#include <algorithm>
#include <cstddef>

#include "improve2d/triangle_angles.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {
namespace {

bool ccw(Vec2 a, Vec2 b, Vec2 c) { return orient2d(a, b, c) == Sign::Positive; }

// p in the bounding box of ab (with orient2d(a, b, p) == 0: p on the closed segment ab).
bool in_box(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// The closed segments ab and cd share a point (exact).
bool closed_segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = int(orient2d(a, b, c)), o2 = int(orient2d(a, b, d));
  const int o3 = int(orient2d(c, d, a)), o4 = int(orient2d(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && in_box(a, b, c)) || (o2 == 0 && in_box(a, b, d)) || (o3 == 0 && in_box(c, d, a)) ||
         (o4 == 0 && in_box(c, d, b));
}

// b strictly inside the interior cone of the CCW polygon q at vertex i (a
// straight vertex has the open half-plane on its left as cone).
bool in_cone(const std::vector<Vec2>& q, std::size_t i, Vec2 b) {
  const std::size_t m = q.size();
  const Vec2 a = q[i], a0 = q[(i + m - 1) % m], a1 = q[(i + 1) % m];
  if (orient2d(a0, a, a1) == Sign::Positive)  // convex: between a->a1 and a->a0
    return orient2d(a, a1, b) == Sign::Positive && orient2d(a, a0, b) == Sign::Negative;
  // reflex or straight: not in the closed exterior cone from a->a0 to a->a1
  return !(orient2d(a, a0, b) != Sign::Negative && orient2d(a, a1, b) != Sign::Positive);
}

// q[i] q[j] (not adjacent) is a diagonal of the simple CCW polygon q: inside
// both end cones, meeting no side away from its ends, through no vertex.
// Each vertex's side of the line q[i] q[j] is computed once: a side whose
// ends are strictly on one side cannot meet the segment, so only the others
// go through closed_segments_meet (the same exact answer, fewer orient2d).
bool is_diagonal(const std::vector<Vec2>& q, std::size_t i, std::size_t j) {
  if (!in_cone(q, i, q[j]) || !in_cone(q, j, q[i])) return false;
  const std::size_t m = q.size();
  auto side = [&](std::size_t k) { return (k == i || k == j) ? 0 : int(orient2d(q[i], q[j], q[k])); };
  int side_k = side(0);
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t k1 = (k + 1) % m;
    const int side_k1 = side(k1);
    if (k != i && k != j && side_k == 0 && in_box(q[i], q[j], q[k])) return false;
    if (k != i && k != j && k1 != i && k1 != j && side_k * side_k1 <= 0 &&
        closed_segments_meet(q[i], q[j], q[k], q[k1]))
      return false;
    side_k = side_k1;
  }
  return true;
}

}  // namespace

// The triangulation of the simple CCW polygon q with the largest min angle
// (dynamic programming over the sub-polygons q[i..j] cut off by a diagonal
// or side ij; first maximum in k order), when that angle exceeds `floor`.
// Returns it (and the triangles in `out`), or a value <= floor when no
// triangulation with every triangle strictly counter-clockwise has all its
// angles above floor. Pruning (the same result as the full table wherever it
// is used): a split k is skipped when its sub-polygons' values cannot beat
// the current best nor floor (the candidate is their min with the new
// triangle's angle), so its diagonals (exact, decided lazily and memoised)
// and its angle are only computed for splits that can win. A sub-polygon
// whose value is <= floor is marked -1 (no candidate through it can pass).
double best_triangulation(const std::vector<Vec2>& q, double floor, std::vector<std::array<int, 3>>& out,
                          DpTables& tables) {
  const int m = int(q.size());
  if (m < 3) return -1;
  auto at = [m](int i, int j) { return std::size_t(i * m + j); };
  std::vector<signed char>& ok = tables.ok;
  ok.assign(std::size_t(m * m), -1);  // -1: not decided yet
  auto diagonal = [&](int i, int j) {
    signed char& d = ok[at(i, j)];
    if (d < 0)
      d = (j == i + 1 || (i == 0 && j == m - 1)) ? 1 : static_cast<signed char>(is_diagonal(q, std::size_t(i), std::size_t(j)));
    return d == 1;
  };
  std::vector<double>& best = tables.best;
  std::vector<int>& arg = tables.arg;
  best.assign(std::size_t(m * m), -1);
  arg.assign(std::size_t(m * m), -1);
  for (int len = 2; len < m; ++len)
    for (int i = 0; i + len < m; ++i) {
      const int j = i + len;
      double& b = best[at(i, j)];
      for (int k = i + 1; k < j; ++k) {
        double sub = 4;  // above every angle
        if (k > i + 1) sub = best[at(i, k)];
        if (j > k + 1) sub = std::min(sub, best[at(k, j)]);
        if (sub <= std::max(b, floor)) continue;  // includes an invalid part (-1)
        if (!diagonal(i, k) || !diagonal(k, j)) continue;
        if (!ccw(q[std::size_t(i)], q[std::size_t(k)], q[std::size_t(j)])) continue;
        const double v = std::min(sub, min_angle(q[std::size_t(i)], q[std::size_t(k)], q[std::size_t(j)]));
        if (v > b && v > floor) {
          b = v;
          arg[at(i, j)] = k;
        }
      }
    }
  if (best[at(0, m - 1)] < 0) return -1;
  out.clear();
  std::vector<std::pair<int, int>>& todo = tables.todo;
  todo.assign(1, {0, m - 1});
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    const int k = arg[at(i, j)];
    out.push_back({i, k, j});
    if (k > i + 1) todo.push_back({i, k});
    if (j > k + 1) todo.push_back({k, j});
  }
  return best[at(0, m - 1)];
}

}  // namespace pqmesh::detail
