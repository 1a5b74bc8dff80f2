// ImprovingCollapses (improving_collapse.hpp).
#include "improve3d/improving_collapse.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "improve3d/smooth.hpp"

namespace pqmesh::improve3d::detail {

std::int64_t ImprovingCollapses::pass() {
  collapser_.forget();
  std::vector<std::pair<double, int>> order;
  for (int t = 0; t < mesh_.tet_count(); ++t)
    if (mesh_.tet(t)[0] >= 0 && mesh_.dihedral(t) < kWorkBelowDihedral) order.emplace_back(mesh_.dihedral(t), t);
  std::sort(order.begin(), order.end());
  std::int64_t collapses = 0;
  for (const auto& [key, t] : order) {
    if (mesh_.tet(t)[0] < 0) continue;
    const std::array<int, 4> k = mesh_.tet(t);
    bool done = false;
    for (std::size_t i = 0; i < 4 && !done; ++i)
      for (std::size_t j = i + 1; j < 4 && !done; ++j) done = collapse_edge(k[i], k[j]);
    if (done) ++collapses;
  }
  return collapses;
}

// The lower class first (Coarsener::collapse_edge in improve.cpp), ties: the smaller id.
bool ImprovingCollapses::collapse_edge(int a, int b) {
  const bool b_first = classes_.of(b) < classes_.of(a) || (classes_.of(b) == classes_.of(a) && b < a);
  const int first = b_first ? b : a, second = b_first ? a : b;
  if (collapser_.try_collapse(first, second)) return true;
  return !collapser_.refused_both_ways() && collapser_.try_collapse(second, first);
}

}  // namespace pqmesh::improve3d::detail
