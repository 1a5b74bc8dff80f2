#pragma once
// Rule 5 of improve.hpp: the user's size function (thesis §1.1, as for
// tet_mesh) h(x) = min(max_size, min_i sizes[i] + |x - points[i]|); an edge
// pq may be created only when |q - p| <= sqrt(3) h(m), m its midpoint (the
// diagonal of a box of side h). A floating-point threshold: it only refuses
// collapses, and every outcome is a valid mesh (docs/DESIGN_RULES.md "Exact
// decisions").
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh::improve3d::detail {

class SizeBound {
 public:
  SizeBound(double max_size, const std::vector<Vec3>& points, const std::vector<double>& sizes)
      : max_size_(max_size > 0 ? max_size : std::numeric_limits<double>::infinity()), points_(points), sizes_(sizes) {}

  bool bounded() const { return max_size_ < std::numeric_limits<double>::infinity() || !points_.empty(); }

  bool allows(Vec3 p, Vec3 q) const {
    const Vec3 m = 0.5 * (p + q);
    double h = max_size_;
    for (std::size_t i = 0; i < points_.size(); ++i) h = std::min(h, sizes_[i] + norm(m - points_[i]));
    return norm(q - p) <= std::sqrt(3.0) * h;
  }

 private:
  double max_size_;
  const std::vector<Vec3>& points_;
  const std::vector<double>& sizes_;
};

}  // namespace pqmesh::improve3d::detail
