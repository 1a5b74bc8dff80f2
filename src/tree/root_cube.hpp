#pragma once
// The root cube of a quadtree/octree and its choice (thesis §4.1.7 step 1: "a single
// node representing a large box with all of the faces of P in its interior").
//
// Exactness (DESIGN.md §3). The side S is a power of two and the origin an integer
// multiple of S/2. Then every box plane origin + S * q / 2^(L+1) equals
// (S/2) * (m * 2^L + q) / 2^L with m = origin / (S/2) an integer, i.e. an integer
// times a power of two, hence an exact double as long as |m * 2^L + q| <= 2^53. The
// tree refuses to split below the level where that stops holding (Tree::max_level()).
//
// Why multiples of S/2 and not of S: a bounding box that straddles a multiple of
// every large power of two (for example [-1, 1], which straddles 0) fits in no cube
// whose origin is a multiple of its own side, however large; with the half-side grid
// any interval shorter than S/2 fits in some cube.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "pqmesh/errors.hpp"

namespace pqmesh {

template <int D>
struct RootCube {
  std::array<double, D> origin{};  // integer multiple of size / 2
  double size = 1;                 // a power of two
};

// Smallest admissible root cube (power-of-two side, origin on a multiple of half the
// side) that contains [lo - m, hi + m] along every axis, with m = margin_fraction *
// (largest extent of the box), or m = 1 when the box is a single point. The input box
// [lo, hi] always ends up strictly inside the root cube. Throws InternalError for
// non-finite or inverted input.
template <int D>
RootCube<D> choose_root_cube(const std::array<double, D>& lo, const std::array<double, D>& hi,
                             double margin_fraction = 0.25) {
  double extent = 0;
  for (int a = 0; a < D; ++a) {
    if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]) || !(lo[a] <= hi[a]))
      throw InternalError("choose_root_cube: bounding box is empty or not finite along axis " +
                          std::to_string(a));
    extent = std::fmax(extent, hi[a] - lo[a]);
  }
  if (!(margin_fraction >= 0) || !std::isfinite(margin_fraction))
    throw InternalError("choose_root_cube: margin_fraction must be finite and >= 0");
  const double margin = extent > 0 ? extent * margin_fraction : 1.0;
  std::array<double, D> want_lo{}, want_hi{};
  double span = 0;
  for (int a = 0; a < D; ++a) {
    want_lo[a] = lo[a] - margin;
    want_hi[a] = hi[a] + margin;
    span = std::fmax(span, want_hi[a] - want_lo[a]);
  }
  int e = 0;
  std::frexp(span, &e);  // span < 2^e
  double size = std::ldexp(1.0, e);
  // With size/2 >= span the test below succeeds unless rounding swallowed the
  // margin (huge coordinates); doubling further then fixes strictness too.
  for (int attempt = 0; attempt < 2100 && std::isfinite(size); ++attempt, size *= 2) {
    const double half = size / 2;
    RootCube<D> root;
    root.size = size;
    bool ok = true;
    for (int a = 0; a < D && ok; ++a) {
      root.origin[a] = std::floor(want_lo[a] / half) * half;  // exact: half is a power of two
      const double top = root.origin[a] + size;               // exact for modest |origin/half|
      ok = root.origin[a] <= want_lo[a] && root.origin[a] < lo[a] && top >= want_hi[a] && top > hi[a] &&
           std::fabs(root.origin[a] / half) < 0x1p50;
    }
    if (ok) return root;
  }
  throw InternalError("choose_root_cube: no representable root cube encloses the bounding box");
}

}  // namespace pqmesh
