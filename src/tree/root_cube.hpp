#pragma once
// The root cube of a quadtree/octree and its choice (thesis §4.1.7 step 1: "a single
// node representing a large box with all of the faces of P in its interior").
//
// Exactness (docs/DESIGN_RULES.md "Exact decisions"). The side S is a power of two
// and the origin an integer multiple of S/2. Then every box plane origin + S * q /
// 2^(L+1) equals (S/2) * (m * 2^L + q) / 2^L with m = origin / (S/2) an integer, i.e.
// an integer times a power of two, hence an exact double as long as |m * 2^L + q| <=
// 2^53. The tree refuses to split below the level where that stops holding
// (Tree::max_level()).
//
// Why multiples of S/2 and not of S: a bounding box that straddles a multiple of
// every large power of two (for example [-1, 1], which straddles 0) fits in no cube
// whose origin is a multiple of its own side, however large; with the half-side grid
// any interval shorter than S/2 fits in some cube.
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pqmesh/errors.hpp"

namespace pqmesh {

template <int D>
struct RootCube {
  std::array<double, D> origin{};  // integer multiple of size / 2
  double size = 1;                 // a power of two
  // Generic grid (choose_generic_root_cube below): added to every box plane
  // along each axis. Zero (the default): the aligned grid of the header comment.
  std::array<double, D> offset{};
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

// ---- Generic grid (docs/algorithm/octree3d.md "Generic grid")
//
// The thesis assumes general position; inputs with dyadic coordinates (a unit
// cube at the origin) put facets in box planes and edges on box edges. The
// generic root is an aligned root (choose_root_cube) whose planes are all
// shifted by an offset `off` per axis, chosen so that no input coordinate
// lies on a box plane of any level <= max_level (returned).
//
// Exactness. Let g = S * 2^-(max_level + 2) and off = K * g with K odd. A
// plane of level L <= max_level is origin + off + N * S / 2^(L+1), an integer
// times g (origin is a multiple of S/2), and every such number of magnitude
// <= bound is an exact double when bound <= 2^53 * g; `bound` covers the root
// and its extended box (2S on each side). max_level is the largest level
// (<= kTreeMaxLevel of tree/key.hpp, passed as `deepest`) with that property.
// Since K is odd, off is not a multiple of the level-max_level spacing 2g, so
// the planes of every level <= max_level (a subset of the level-max_level
// planes) are all shifted off the aligned grid.
//
// Which coordinates hit a plane. Every plane of level <= max_level is among
// the planes of level max_level, origin + off + n * 2g, and origin is a
// multiple of 2g, so c lies on some plane iff c - off is a multiple of 2g,
// i.e. iff c is an ODD multiple of g (K is odd). A coordinate with bits
// finer than g (0.1) or an even multiple of g (0.5, 1) never does, whatever
// the offset's coarser bits. The test is exact: the plane numbers around the
// floating-point estimate of n are compared as exact doubles (the estimate is
// off by less than 1).
//
// Offsets. off/S = the fraction of (a + 1 + 3 * shift) * 0.6180339887498949
// (the golden ratio's fraction, a double constant: the same on every machine;
// `shift` numbers alternative offsets, 0 the default) scaled to
// [0, 1/32), rounded down to a multiple of 2g, plus g: its coarse bits place
// dyadic coordinates at irregular positions inside the boxes of every level,
// not at a tiny distance from a plane. If a coordinate is an odd multiple of
// g, the next candidate lowers max_level by one (g doubles: c is then an odd
// multiple of g/2, on no plane); a number is an odd multiple of exactly one
// power of two, so with n coordinates at most n candidates fail. After 24
// failures (or if the root does not hold the input box strictly) the margin
// doubles. In practice candidate 0 is taken (the whole corpus).
template <int D>
struct GenericRoot {
  RootCube<D> root;          // root.offset is the shift
  std::int32_t max_level = 0;  // deepest level whose planes stay exact and miss every coordinate
  int candidate = 0;           // levels given up below the deepest exact one (0 unless a coordinate hit a plane)
};

namespace detail {

// True when c lies on a plane base + n * 2g (n an integer, base = origin +
// off, g = 2^ge), i.e. on a box plane of level max_level. Exact comparisons
// only (see above).
inline bool on_generic_plane(double c, double origin, double off, int ge) {
  const double step = std::ldexp(2.0, ge);
  const double t = std::floor((c - (origin + off)) / step);
  // base / g and candidate plane numbers are integers below 2^53 (bound check).
  const double base_units = std::ldexp(origin, -ge) + std::ldexp(off, -ge);
  for (double k = t - 1; k <= t + 1; k += 1) {
    const double plane = std::ldexp(base_units + 2 * k, ge);  // exact: an integer < 2^53 times g
    if (plane == c) return true;
  }
  return false;
}

}  // namespace detail

// coords[a]: every input coordinate along axis a. `deepest`: the finest level
// a tree may use (kTreeMaxLevel). `shift` (>= 0): which offset sequence
// (above); distinct shifts put the box planes at unrelated places relative
// to the input. Throws InternalError for non-finite input or when no
// candidate is found.
template <int D>
GenericRoot<D> choose_generic_root_cube(const std::array<double, D>& lo, const std::array<double, D>& hi,
                                        const std::array<std::span<const double>, D>& coords, int deepest,
                                        int shift = 0) {
  constexpr double kGolden = 0.6180339887498949;
  for (int a = 0; a < D; ++a)
    for (const double c : coords[a])
      if (!std::isfinite(c)) throw InternalError("choose_generic_root_cube: non-finite coordinate");
  for (double margin = 0.25; margin < 1e6; margin *= 2) {
    const RootCube<D> base = choose_root_cube<D>(lo, hi, margin);
    int se = 0;
    std::frexp(base.size, &se);
    se -= 1;  // size = 2^se
    double reach = 0;  // largest |plane| of the root and its extended box, offset included
    for (int a = 0; a < D; ++a)
      reach = std::fmax(reach, std::fmax(std::fabs(base.origin[a]), std::fabs(base.origin[a] + base.size)));
    reach += 2.0 * base.size + base.size / 32;
    // Largest L with reach <= 2^53 * S * 2^-(L+2), i.e. reach / S <= 2^(51 - L).
    std::int32_t top = deepest;
    while (top > 1 && reach / base.size > std::ldexp(1.0, 51 - top)) --top;
    if (reach / base.size > std::ldexp(1.0, 51 - top))
      throw InternalError("choose_generic_root_cube: coordinates too large for an exact grid");
    for (int j = 0; j < 24 && top - j >= 1; ++j) {
      const std::int32_t level = top - j;
      const int ge = se - level - 2;  // g = 2^ge
      if (ge < -1021) continue;
      GenericRoot<D> out;
      out.root = base;
      out.max_level = level;
      out.candidate = j;
      bool ok = true;
      for (int a = 0; a < D && ok; ++a) {
        const double x = static_cast<double>(a + 1 + 3 * shift) * kGolden;
        const double frac = x - std::floor(x);  // in [0, 1)
        // K = 2 * floor(frac / 32 * 2^(level + 1)) + 1: off = K * g < S / 32.
        const double half_units = std::floor(std::ldexp(frac, level + 1 - 5));
        const double off = std::ldexp(2 * half_units + 1, ge);
        out.root.offset[a] = off;
        const double o = base.origin[a] + off;  // exact (see above)
        ok = o < lo[a] && o + base.size > hi[a];
        // The Tree constructor's own check (tree_impl.hpp), verbatim: the
        // planes of the root and its extended box, origin - 2S to origin +
        // 3S shifted by off = K * 2^ge (K odd, so 2^ge is off's lowest bit),
        // are exact doubles. Implied by `reach` above when off < S/32, which
        // the coarsest levels (level <= 3: off = g >= S/32) do not give; tested
        // here so that every returned root is accepted by construction.
        const double planes = std::fmax(std::fabs(base.origin[a] - 2 * base.size),
                                        std::fabs(base.origin[a] + 3 * base.size)) + std::fabs(off);
        ok = ok && planes <= std::ldexp(1.0, 53 + ge);
        for (std::size_t i = 0; ok && i < coords[a].size(); ++i)
          ok = !detail::on_generic_plane(coords[a][i], base.origin[a], off, ge);
      }
      if (ok) return out;
    }
  }
  throw InternalError("choose_generic_root_cube: no generic offset found");
}

}  // namespace pqmesh
