// ImprovingCollapses (improving_collapse.hpp).
#include "improve3d/improving_collapse.hpp"

#include <array>
#include <cstddef>

#include "improve3d/worst_first.hpp"

namespace pqmesh::improve3d::detail {

std::int64_t ImprovingCollapses::pass() {
  collapser_.forget();
  return visit_worst_first(mesh_, [this](int t) { return collapse_tet(t); });
}

// The first of t's six edges, in the order (0 1) (0 2) (0 3) (1 2) (1 3) (2 3), that collapses.
bool ImprovingCollapses::collapse_tet(int t) {
  const std::array<int, 4> k = mesh_.tet(t);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      if (collapse_edge(k[i], k[j])) return true;
  return false;
}

// The lower class first (Coarsener::collapse_edge in improve.cpp), ties: the smaller id.
bool ImprovingCollapses::collapse_edge(int a, int b) {
  const bool b_first = classes_.of(b) < classes_.of(a) || (classes_.of(b) == classes_.of(a) && b < a);
  const int first = b_first ? b : a, second = b_first ? a : b;
  if (collapser_.try_collapse(first, second)) return true;
  return !collapser_.refused_both_ways() && collapser_.try_collapse(second, first);
}

}  // namespace pqmesh::improve3d::detail
