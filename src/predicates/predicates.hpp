#pragma once
// Exact geometric predicates (docs/DESIGN_RULES.md "Exact decisions").
//
// Every predicate returns the exact sign of a polynomial in the input
// coordinates, which are taken as the exact binary values of the doubles.
// Implementation: the determinant is evaluated in double together with a
// bound on its rounding error (a constant times machine epsilon times the
// permanent, the same expression with every term replaced by its absolute
// value); when the double result does not clear the bound, the determinant is
// recomputed exactly: orient2d and incircle first try an error-free
// evaluation in doubles (exact for few-bit coordinates such as quadtree grid
// corners), orient2d then an exact expansion sum (any coordinates in a wide
// range), and whatever is left goes to GMP rationals. There are no
// tolerances: Zero means exactly degenerate.
//
// Tie-break: the predicates report Zero honestly. A caller that must decide a
// degenerate case does so by a symbolic perturbation documented at the call
// site (docs/algorithm/predicates.md "Where ties are broken" lists them), never
// by a tolerance.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "pqmesh/vec.hpp"

namespace pqmesh {

enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign sign_of(double v) { return v > 0 ? Sign::Positive : (v < 0 ? Sign::Negative : Sign::Zero); }
constexpr Sign operator*(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }

namespace detail {
constexpr double kPredicateEps = std::numeric_limits<double>::epsilon();  // 2^-52
// Below this permanent the error analysis could be spoiled by underflow, so
// the double filter never decides (the later stages do).
constexpr double kTinyPermanent = 1e-280;
// The double filter of every predicate. det is the determinant evaluated in
// double, permanent the same expression with every term replaced by its
// absolute value, and factor * eps * permanent bounds the rounding error of
// det (each predicate states its factor). Returns true with the sign when det
// clears the bound, or with Zero when the permanent is exactly 0 and
// `no_tiny_factor()` holds (then no product of nonzero factors underflowed, so
// every term has a zero factor and the determinant is exactly 0); false (sign
// untouched) when a later, exact stage must decide: det within the bound, a
// permanent so small that underflow could spoil the bound, a zero permanent
// that may come from underflow, or a NaN. The factors are
// deliberately generous (a few times what a careful rounding analysis gives
// for each expression tree): a too large bound only sends more cases to the
// exact stages, never a wrong sign. (An out-parameter, not std::optional: the
// inline callers then compile to plain branches.)
template <class NoTinyFactor>
constexpr bool filtered_sign(double det, double permanent, double factor, Sign& sign, NoTinyFactor no_tiny_factor) {
  if (permanent > kTinyPermanent) {
    const double bound = factor * kPredicateEps * permanent;
    if (det > bound) {
      sign = Sign::Positive;
      return true;
    }
    if (-det > bound) {
      sign = Sign::Negative;
      return true;
    }
    return false;
  }
  if (permanent == 0 && no_tiny_factor()) {
    sign = Sign::Zero;
    return true;
  }
  return false;
}
// True when every factor (a coordinate difference) is zero or at least 2^-200
// in magnitude: a product of up to five such nonzero factors (insphere's lift
// times a 3x3 minor) is at least 2^-1000 and cannot underflow to zero. Only
// evaluated when a permanent is exactly 0.
template <class... Factors>
constexpr bool no_tiny_factor(Factors... f) {
  return ((f == 0 || f >= 0x1p-200 || f <= -0x1p-200) && ...);
}
// The stages after the double filter (predicates.cpp): the error-free
// "certified" evaluation, then (orient2d) an exact expansion sum, then GMP.
// Called only when the inline filter below cannot decide.
Sign orient2d_after_filter(Vec2 a, Vec2 b, Vec2 c);
Sign incircle_after_filter(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
Sign dot_sign_after_filter(Vec2 a, Vec2 b, Vec2 c);
Sign dot_sign_after_filter(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
// The expansion stage of orient2d on its own (for tests): the exact sign of
// det(a - c, b - c) from twelve error-free products summed as a
// nonoverlapping expansion (no rounding anywhere), after scaling each axis
// by a power of two. Returns false (no answer) when the coordinates are not
// finite or the nonzero magnitudes on one axis span more than about 2^400.
bool orient2d_expansion(Vec2 a, Vec2 b, Vec2 c, Sign& sign);
// The first stage of incircle after the filter, on its own (for tests): when
// the six differences a - d, ..., c - d are exact and are all k 2^u for
// integers |k| < 2^12 (one u; quadtree grid corners near each other), every
// value of the double evaluation is an integer times a power of 2^u below
// 2^53, so it is exact and its sign is the answer. Returns false otherwise.
bool incircle_small_integer(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Sign& sign);
// The expansion stages of dot_sign on their own (for tests): the exact sign
// of (b - a) . (d - c) (2D: of (b - a) . (c - a)) as a sum of error-free
// products. When the coordinate differences are exact (Knuth's
// two-difference; grid points, which are massively at right angles) it sums
// the 2 or 3 products of the differences, otherwise the 8 or 12 products of
// the coordinates themselves, (b - a) . (d - c) = sum_i b_i d_i - b_i c_i -
// a_i d_i + a_i c_i. Each factor group is scaled by one power of two (the
// sign is unchanged). Returns false (no answer) when a coordinate is not
// finite or the nonzero magnitudes of a group span more than about 2^400.
bool dot_sign_expansion(Vec2 a, Vec2 b, Vec2 c, Sign& sign);
bool dot_sign_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign& sign);
// The expansion stage of orient3d on its own (for tests): when the nine
// differences b - a, c - a, d - a are exact, the six triple products of
// det(b - a, c - a, d - a), each split into four doubles without rounding
// (two nested two-products), summed as an expansion; each axis (column) is
// scaled by a power of two first. When a difference is not exact (points
// near a slanted facet plane), the same with the 24 triple products of raw
// coordinates of det(b, c, d) - det(a, c, d) - det(b, a, d) - det(b, c, a).
// Returns false (then GMP decides) when a column's (axis's) nonzero
// magnitudes span more than about 2^250 (triple products must stay far from
// underflow) or a value is not finite.
bool orient3d_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign& sign);
}  // namespace detail

// Positive when a, b, c turn counter-clockwise: sign of det(b - a, c - a).
// The double filter is inline (it decides almost every call; the mesher calls
// this tens of millions of times): the determinant in double with the error
// bound 8 eps times the permanent |l| + |r| (a few times the bound a careful
// rounding analysis gives); a permanent of exactly 0 means every term is 0
// unless a product underflowed (detail::no_tiny_factor).
inline Sign orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double acx = a.x - c.x, bcx = b.x - c.x, acy = a.y - c.y, bcy = b.y - c.y;
  const double l = acx * bcy, r = acy * bcx;
  const double det = l - r;
  const double permanent = std::abs(l) + std::abs(r);
  if (Sign s{}; detail::filtered_sign(det, permanent, 8, s, [&] { return detail::no_tiny_factor(acx, bcx, acy, bcy); }))
    return s;
  return detail::orient2d_after_filter(a, b, c);
}

// Positive when det(b - a, c - a, d - a) > 0: d lies on the side of triangle
// abc that its right-hand normal points to (positive tetrahedron volume).
Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// orient2d of the projections of a, b, c onto the coordinate plane that drops
// axis `drop` (0 = x, 1 = y, 2 = z); the remaining axes keep their cyclic
// order (drop x -> (y, z), drop y -> (z, x), drop z -> (x, y)), so for a planar
// polygon with normal n the sign equals sign(n[drop]) times its true turn.
Sign orient2d_projected(Vec3 a, Vec3 b, Vec3 c, int drop);

// Positive when d lies strictly inside the circle through a, b, c, which must
// be counter-clockwise (the sign flips for a clockwise triangle). Inline
// double filter as for orient2d, error bound 32 eps times the permanent.
inline Sign incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdx * cdy - bdy * cdx) + blift * (cdx * ady - cdy * adx) + clift * (adx * bdy - ady * bdx);
  const double permanent = alift * (std::abs(bdx * cdy) + std::abs(bdy * cdx)) +
                           blift * (std::abs(cdx * ady) + std::abs(cdy * adx)) +
                           clift * (std::abs(adx * bdy) + std::abs(ady * bdx));
  if (Sign s{}; detail::filtered_sign(det, permanent, 32, s,
                                      [&] { return detail::no_tiny_factor(adx, ady, bdx, bdy, cdx, cdy); }))
    return s;
  return detail::incircle_after_filter(a, b, c, d);
}

// Positive when e lies strictly inside the sphere through a, b, c, d, which
// must have orient3d(a, b, c, d) > 0 (the sign flips otherwise).
Sign insphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e);

// Sign of the dot product (b - a) . (c - a): Positive when the angle bac is
// acute, Zero when right, Negative when obtuse. Inline double filter (error
// bound 8 eps times the permanent), then the expansion stage
// (detail::dot_sign_expansion), then GMP.
inline Sign dot_sign(Vec2 a, Vec2 b, Vec2 c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  const double l = ux * vx, r = uy * vy;
  const double det = l + r, permanent = std::abs(l) + std::abs(r);
  if (Sign s{}; detail::filtered_sign(det, permanent, 8, s, [&] { return detail::no_tiny_factor(ux, uy, vx, vy); }))
    return s;
  return detail::dot_sign_after_filter(a, b, c);
}

// Sign of (b - a) . (d - c) for two independent directions. Inline double
// filter (error bound 8 eps times the permanent; the quality fields call this
// twelve times per tetrahedron), then the expansion stage, then GMP.
inline Sign dot_sign(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = d.x - c.x, vy = d.y - c.y, vz = d.z - c.z;
  const double px = ux * vx, py = uy * vy, pz = uz * vz;
  const double det = px + py + pz, permanent = std::abs(px) + std::abs(py) + std::abs(pz);
  if (Sign s{}; detail::filtered_sign(det, permanent, 8, s,
                                      [&] { return detail::no_tiny_factor(ux, uy, uz, vx, vy, vz); }))
    return s;
  return detail::dot_sign_after_filter(a, b, c, d);
}
// Sign of (b - a) . (c - a), as in 2D.
inline Sign dot_sign(Vec3 a, Vec3 b, Vec3 c) { return dot_sign(a, b, a, c); }

// Sign of a - b for two coordinates (trivially exact; named for clarity).
constexpr Sign compare(double a, double b) { return a > b ? Sign::Positive : (a < b ? Sign::Negative : Sign::Zero); }

// The neighbouring doubles of x: the same values as std::nextafter(x, +inf)
// and std::nextafter(x, -inf) for every x (NaN stays NaN, +-0 steps to the
// smallest subnormal of the step's sign, -denorm_min up gives -0, +-inf and
// +-max step as nextafter does), from the bits instead of a library call: on
// one sign the order of finite doubles is the order of their bit patterns.
// The ulp box tests below call them for every point they examine.
inline double next_up(double x) {
  if (x != x || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0 ? bits + 1 : bits - 1);
}
inline double next_down(double x) { return -next_up(-x); }

// p is a faithful rounding of a point of the closed segment ab: the segment
// meets the closed "ulp box" [pred(p.x), succ(p.x)] x [pred(p.y), succ(p.y)]
// (pred/succ: the neighbouring doubles). A mesher that puts a Steiner point on
// a slanted input segment cannot, in general, store it exactly (the exact
// point has no double coordinates); it stores a rounding of it, and this is
// the rule by which the checker (src/mesh) accepts it as lying on the
// segment (docs/algorithm/quality.md "The validity checker"). Exact: a
// separating-axis test with the two box axes and the segment's normal, the
// latter by orient2d on the corners.
inline bool segment_meets_rect(Vec2 a, Vec2 b, Vec2 lo, Vec2 hi);

inline bool within_ulp_of_segment(Vec2 p, Vec2 a, Vec2 b) {
  return segment_meets_rect(a, b, {next_down(p.x), next_down(p.y)}, {next_up(p.x), next_up(p.y)});
}

// The closed segment ab meets the closed rectangle [lo, hi] (lo <= hi). Exact:
// separating axes x, y and the segment's normal (orient2d on the corners).
inline bool segment_meets_rect(Vec2 a, Vec2 b, Vec2 lo, Vec2 hi) {
  if (hi.x < std::min(a.x, b.x) || lo.x > std::max(a.x, b.x) || hi.y < std::min(a.y, b.y) ||
      lo.y > std::max(a.y, b.y))
    return false;
  int pos = 0, neg = 0;
  for (const Vec2 c : {lo, Vec2{hi.x, lo.y}, hi, Vec2{lo.x, hi.y}}) {
    const Sign s = orient2d(a, b, c);
    pos += s == Sign::Positive;
    neg += s == Sign::Negative;
  }
  return pos < 4 && neg < 4;
}

// The 3D forms of the same rule, for Steiner points on slanted input edges and
// facets (docs/algorithm/quality.md "The validity checker"). The ulp box of p
// is [pred(p.x), succ(p.x)] x [pred(p.y), succ(p.y)] x [pred(p.z), succ(p.z)].
//
// within_ulp_of_segment(p, a, b): the closed segment ab meets p's ulp box.
// Exact separating-axis test: the three box axes (interval overlap) and the
// three products e_i x (b - a); along e_i x (b - a) the segment projects to
// one point and a corner c to the sign of orient2d_projected(a, b, c, i), so
// the axis separates iff the four distinct projected corners lie strictly on
// one side of the projected line.
inline bool within_ulp_of_segment(Vec3 p, Vec3 a, Vec3 b) {
  const double pc[3] = {p.x, p.y, p.z}, ac[3] = {a.x, a.y, a.z}, bc[3] = {b.x, b.y, b.z};
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    lo[i] = next_down(pc[i]);
    hi[i] = next_up(pc[i]);
    if (hi[i] < std::min(ac[i], bc[i]) || lo[i] > std::max(ac[i], bc[i])) return false;
  }
  for (int drop = 0; drop < 3; ++drop) {
    const int u = (drop + 1) % 3, w = (drop + 2) % 3;
    int pos = 0, neg = 0;
    for (int corner = 0; corner < 4; ++corner) {
      // The corners of the box's projection along `drop` (the dropped
      // coordinate does not enter orient2d_projected).
      double c[3] = {lo[0], lo[1], lo[2]};
      c[u] = (corner & 1) ? hi[u] : lo[u];
      c[w] = (corner & 2) ? hi[w] : lo[w];
      const Sign s = orient2d_projected(a, b, {c[0], c[1], c[2]}, drop);
      pos += s == Sign::Positive;
      neg += s == Sign::Negative;
    }
    if (pos == 4 || neg == 4) return false;
  }
  return true;
}

// within_ulp_of_plane(p, a, b, c): the plane through a, b, c (not collinear)
// meets p's ulp box: orient3d is not of one strict sign on its eight corners.
inline bool within_ulp_of_plane(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const double xs[2] = {next_down(p.x), next_up(p.x)};
  const double ys[2] = {next_down(p.y), next_up(p.y)};
  const double zs[2] = {next_down(p.z), next_up(p.z)};
  int pos = 0, neg = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Sign s = orient3d(a, b, c, {xs[corner & 1], ys[(corner >> 1) & 1], zs[(corner >> 2) & 1]});
    pos += s == Sign::Positive;
    neg += s == Sign::Negative;
  }
  return pos < 8 && neg < 8;
}

}  // namespace pqmesh
