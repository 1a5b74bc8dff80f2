#pragma once
// Rule 5 of improve.hpp: the user's size function (thesis §1.1, as for
// tet_mesh) h(x) = min(max_size, min_i sizes[i] + |x - points[i]|); a
// tetrahedron may be made only when its longest edge is at most sqrt(3) h(g),
// g its centroid (the diagonal of a box of side h: what the construction's
// tetrahedra meet, except cones from an input vertex across a united vertex
// box, up to 2.32 h at the unit cube's corners). A floating-point threshold: it only refuses operations,
// and every outcome is a valid mesh (docs/DESIGN_RULES.md "Exact decisions").
#include <algorithm>
#include <array>
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

  // With max_size only (no size points) the bound is one length: allows(t)
  // is false whenever some edge of t is longer than longest_edge_bound()
  // (the same floating-point comparison), so a caller may refuse early on one edge.
  bool uniform() const { return points_.empty(); }
  double longest_edge_bound() const { return std::sqrt(3.0) * max_size_; }

  bool allows(const std::array<Vec3, 4>& t) const {
    const Vec3 g = 0.25 * (t[0] + t[1] + t[2] + t[3]);
    double h = max_size_;
    for (std::size_t i = 0; i < points_.size(); ++i) h = std::min(h, sizes_[i] + norm(g - points_[i]));
    return longest_edge(t) <= std::sqrt(3.0) * h;
  }

  static double longest_edge(const std::array<Vec3, 4>& t) {
    double longest = 0;
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t b = a + 1; b < 4; ++b) longest = std::max(longest, norm(t[a] - t[b]));
    return longest;
  }

 private:
  double max_size_;
  const std::vector<Vec3>& points_;
  const std::vector<double>& sizes_;
};

}  // namespace pqmesh::improve3d::detail
