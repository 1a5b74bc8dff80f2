// g(P), the upper bound on the min angle of any triangulation without
// boundary Steiner points (thesis ch. 5 introduction, Theorems 17, 21), from
// the empty spirals of all (V, E) pairs; the constant is derived in
// docs/algorithm/nosteiner2d.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "nosteiner2d/stages.hpp"

namespace pqmesh {

double SteinerFreeBound::upper_bound() const { return std::min(std::numbers::pi / 3, kSteinerFreeBoundConstant * g); }

SteinerFreeBound steiner_free_bound(const Domain2& domain, const SteinerFreeOptions& options) {
  SteinerFreeBound b;
  b.spirals = empty_spirals(domain, options);
  b.vertex_term = std::numeric_limits<double>::infinity();
  b.pair_term = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(b.spirals.size()); ++i) {
    const EmptySpiral& e = b.spirals[i];
    // Every triangle at V has its angle there <= alpha_V (each (V, E) pair
    // sees the same alpha twice; the first occurrence wins ties).
    if (e.alpha < b.vertex_term) {
      b.vertex_term = e.alpha;
      b.vertex_term_vertex = e.vertex;
    }
    if (e.has_eligible && e.min_h < b.pair_term) {
      b.pair_term = e.min_h;
      b.pair_spiral = i;
    }
  }
  b.g = std::min(b.vertex_term, b.pair_term);
  return b;
}

}  // namespace pqmesh
