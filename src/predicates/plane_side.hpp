#pragma once
// orient3d(a, b, c, d) for one fixed triangle a, b, c and many points d (the
// points the 3D mesher settles onto a slanted facet plane,
// docs/algorithm/predicates.md and docs/algorithm/mesh3d.md), with an exact
// stage cheaper than orient3d's own.
//
// det(b - a, c - a, d - a) = N . d - K with N = (b - a) x (c - a) =
// b x c + c x a + a x b and K = a . (b x c) = det(a, b, c), exactly (the
// terms with a repeated row vanish). N's components (six coordinate products
// each) and K (six triple products) are computed once, exactly, as compressed
// expansions; a point then costs three scalings of a few components by one
// coordinate, summed exactly, instead of orient3d's 24 raw triple products
// (the points near a slanted plane never have exact differences d - a).
// Range: every coordinate of a, b, c, d zero or of magnitude in
// [2^-150, 2^150]. Then every exact product of two coordinates is a multiple
// of 2^-404 (each coordinate is a multiple of 2^-202), N's components and
// the parts of K are multiples of 2^-404 and 2^-606, their products with a
// coordinate of d multiples of 2^-606, all far above the subnormal range and
// below 2^460: Dekker's products and the two-sums are exact. A coordinate of
// d below 2^-950 in magnitude (ulp box corners of points on an axis plane,
// +-2^-1074) is decided by magnitude (expansion_sign). Outside the range
// (or for a non-finite coordinate) the point goes to orient3d itself.
// Same answer as orient3d in every case: both are the exact sign.
#include <array>

#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {

class PlaneSide {
 public:
  // a, b, c: any three points (collinear ones give N = 0: then every point
  // is Zero, as for orient3d).
  PlaneSide(Vec3 a, Vec3 b, Vec3 c);
  // The sign of orient3d(a, b, c, d): the double filter, then the plane's
  // expansion stage (or orient3d's own stages outside the range).
  Sign operator()(Vec3 d) const;
  // within_ulp_of_plane(p, a, b, c) (predicates.hpp), decided on the two
  // extreme corners of p's ulp box instead of eight: orient3d(a, b, c, x) is
  // the sign of an affine function of x with gradient N, largest over the
  // box at the corner taking the upper bound where N_i > 0 and the lower
  // where N_i < 0 (either where N_i = 0) and smallest at the opposite
  // corner; all eight corners are strictly on one side exactly when both
  // extremes are. N's signs are exact (orient2d_projected, once).
  bool meets_ulp_box(Vec3 p) const;
  // The exact expansion stage on its own (for tests): false when a
  // coordinate of a, b, c or d is outside the range above, or when two
  // coordinates of d are tiny and the rest of the sum is exactly zero.
  bool expansion_sign(Vec3 d, Sign& sign) const;

 private:
  Vec3 a_, b_, c_;
  std::array<Sign, 3> normal_{};
  bool in_range_ = false;
  // N's components and -K as compressed expansions (exact sums).
  double n_[3][12] = {};
  int n_len_[3] = {};
  double minus_k_[24] = {};
  int k_len_ = 0;
};

}  // namespace pqmesh
