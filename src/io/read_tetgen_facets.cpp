#include "io/read_tetgen_facets.hpp"

#include <cmath>

#include "predicates/predicates.hpp"

namespace pqmesh::detail {

namespace {

enum class Where { Inside, Boundary, Outside };

// Exact winding-number test of q against the polygon projected by dropping
// `drop` (axes u, v in orient2d_projected's cyclic order).
Where locate(const std::vector<Vec3>& V, const std::vector<int>& poly, const Vec3& q, int drop) {
  const int ua = (drop + 1) % 3, va = (drop + 2) % 3;
  const double qu = axis_coord(q, ua), qv = axis_coord(q, va);
  int winding = 0;
  const std::size_t k = poly.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3& a = V[poly[i]];
    const Vec3& b = V[poly[(i + 1) % k]];
    const Sign o = orient2d_projected(a, b, q, drop);
    const double au = axis_coord(a, ua), av = axis_coord(a, va), bu = axis_coord(b, ua), bv = axis_coord(b, va);
    if (o == Sign::Zero && std::min(au, bu) <= qu && qu <= std::max(au, bu) && std::min(av, bv) <= qv &&
        qv <= std::max(av, bv))
      return Where::Boundary;
    if (av <= qv) {
      if (bv > qv && o == Sign::Positive) ++winding;
    } else if (bv <= qv && o == Sign::Negative) {
      --winding;
    }
  }
  return winding != 0 ? Where::Inside : Where::Outside;
}

bool encloses(const std::vector<Vec3>& V, const std::vector<int>& outer, const std::vector<int>& inner, int drop) {
  bool inside = false;
  for (int v : inner) {
    const Where w = locate(V, outer, V[v], drop);
    if (w == Where::Outside) return false;
    inside = inside || w == Where::Inside;
  }
  if (inside) return true;
  for (std::size_t i = 0; i < inner.size(); ++i) {
    const Vec3 mid = 0.5 * (V[inner[i]] + V[inner[(i + 1) % inner.size()]]);
    const Where w = locate(V, outer, mid, drop);
    if (w == Where::Outside) return false;
    if (w == Where::Inside) return true;
  }
  return false;  // same outline as `outer`
}

int facet_drop(const std::vector<Vec3>& V, const std::vector<std::vector<int>>& polygons) {
  Vec3 best;
  for (const auto& poly : polygons) {
    Vec3 n;
    const Vec3 o = V[poly[0]];
    for (std::size_t i = 0; i < poly.size(); ++i) n = n + cross(V[poly[i]] - o, V[poly[(i + 1) % poly.size()]] - o);
    if (norm(n) > norm(best)) best = n;
  }
  return dominant_axis(best);
}

}  // namespace

std::string split_tetgen_facet(const std::vector<Vec3>& V, const std::vector<std::vector<int>>& polygons,
                               const std::vector<Vec3>& hole_points, int marker, std::vector<Facet3>& out) {
  const std::size_t n = polygons.size();
  if (n == 1) {
    out.push_back({{polygons[0]}, marker});
    return {};
  }
  const int drop = facet_drop(V, polygons);
  // enclosed[i * n + j]: polygon i encloses polygon j.
  std::vector<char> enclosed(n * n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j) enclosed[i * n + j] = encloses(V, polygons[i], polygons[j], drop) ? 1 : 0;
  std::vector<char> hole(n, 0);
  for (std::size_t h = 0; h < hole_points.size(); ++h) {
    std::vector<std::size_t> containing;
    for (std::size_t i = 0; i < n; ++i)
      if (locate(V, polygons[i], hole_points[h], drop) == Where::Inside) containing.push_back(i);
    if (containing.empty()) continue;  // a hole point outside every polygon removes nothing
    std::size_t innermost = n;
    for (std::size_t c : containing) {
      bool inner_most = true;
      for (std::size_t d : containing)
        if (d != c && !enclosed[d * n + c]) inner_most = false;
      if (inner_most) innermost = c;
    }
    if (innermost == n) return "the polygons around facet hole point " + std::to_string(h + 1) + " overlap";
    hole[innermost] = 1;
  }
  // Parent of each polygon: its innermost enclosing non-hole polygon.
  std::vector<long> parent(n, -1);
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      if (i == j || hole[i] || !enclosed[i * n + j]) continue;
      if (parent[j] < 0 || enclosed[static_cast<std::size_t>(parent[j]) * n + i]) parent[j] = static_cast<long>(i);
    }
    if (hole[j] && parent[j] < 0)
      return "hole polygon " + std::to_string(j + 1) + " lies in no other polygon of the facet";
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (hole[i]) continue;
    Facet3 f;
    f.marker = marker;
    f.loops.push_back(polygons[i]);
    for (std::size_t j = 0; j < n; ++j)
      if (parent[j] == static_cast<long>(i)) f.loops.push_back(polygons[j]);
    out.push_back(std::move(f));
  }
  return {};
}

}  // namespace pqmesh::detail
