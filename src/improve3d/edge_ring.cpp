#include "improve3d/edge_ring.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>

#include "improve3d/permutation.hpp"

namespace pqmesh::improve3d::detail {

namespace {

int position(const std::array<int, 4>& k, int x) {
  return static_cast<int>(std::distance(k.begin(), std::find(k.begin(), k.end(), x)));
}

}  // namespace

bool gather_edge_ring(const CollapseMesh& mesh, int a, int b, std::span<const int> tets_of_a, int max_tets,
                      EdgeRing& out) {
  out.a = a;
  out.b = b;
  out.ring.clear();
  out.tets.clear();
  std::vector<std::array<int, 3>> arcs;  // (x, y, tet) with (a, b, x, y) even
  for (const int t : tets_of_a) {
    const std::array<int, 4>& k = mesh.tet(t);
    const int j = position(k, b);
    if (j == 4) continue;
    if (static_cast<int>(arcs.size()) == max_tets) return false;
    const std::array<int, 4> p = starting_with(k, position(k, a), j);
    arcs.push_back({p[2], p[3], t});
  }
  if (arcs.empty()) return false;
  const auto from = [&](int x) {
    return std::find_if(arcs.begin(), arcs.end(), [&](const std::array<int, 3>& e) { return e[0] == x; });
  };
  // Open when some arc's start ends no arc; closed rings start at their smallest vertex.
  int start = -1;
  for (const auto& e : arcs)
    if (std::none_of(arcs.begin(), arcs.end(), [&](const std::array<int, 3>& f) { return f[1] == e[0]; })) {
      if (start >= 0) return false;  // two fans
      start = e[0];
    }
  out.closed = start < 0;
  if (out.closed)
    for (const auto& e : arcs) start = start < 0 ? e[0] : std::min(start, e[0]);
  int x = start;
  for (std::size_t n = 0; n < arcs.size(); ++n) {
    const auto e = from(x);
    if (e == arcs.end()) return false;
    out.ring.push_back(x);
    out.tets.push_back((*e)[2]);
    x = (*e)[1];
  }
  if (out.closed != (x == start)) return false;
  if (!out.closed) out.ring.push_back(x);
  return true;
}

}  // namespace pqmesh::improve3d::detail
