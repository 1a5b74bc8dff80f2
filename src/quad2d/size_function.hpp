#pragma once
// The user size function of thesis §1.1 ("the largest desired box containing
// that point") for the quadtree: a global cap and a field of points with sizes
// (include/pqmesh/quadmesh.hpp). A box is split while its side exceeds the
// smallest size asked anywhere in it.
#include "pqmesh/quadmesh.hpp"
#include "quad2d/components2d.hpp"

namespace pqmesh::quad2d {

class SizeFunction2 {
 public:
  // Throws InvalidInput naming the offending field entry (and its file line) for a
  // non-finite point, a size that is not a positive finite number, or a negative
  // or non-finite max_size.
  explicit SizeFunction2(const QuadMeshOptions& options);
  bool active() const { return max_size_ > 0 || !field_.points.empty(); }
  // The global cap (0: none); the field only asks for smaller boxes.
  double max_size() const { return max_size_; }
  // No field: min_over is the same number for every square.
  bool uniform() const { return field_.points.empty(); }
  // min over x in the closed square of f(x), f(x) = min(max_size, min_i sizes[i] + |x - points[i]|).
  double min_over(const Square& square) const;

 private:
  double max_size_ = 0;
  SizeField2 field_;
};

}  // namespace pqmesh::quad2d
