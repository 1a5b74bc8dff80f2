#include "predicates/predicates.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "predicates/expansion.hpp"

namespace pqmesh {
namespace {

using detail::add_triple_product;
using detail::Expansion;
using detail::split_veltkamp;
using detail::two_product;

Sign sign_of_mpq(const mpq_class& v) { return static_cast<Sign>(sgn(v)); }

// Second stage, before GMP: evaluate the same expression with error-free
// transformations (TwoSum; Dekker's product error with Veltkamp's split) and
// keep a flag that stays true only while every operation is exact. When it
// does, the double result IS the exact value and its sign is the answer. This
// is the common case for the quadtree meshes' vertices (dyadic grid corners
// with few significant bits), which are massively cocircular and collinear:
// the filter cannot decide a determinant that is exactly zero, and GMP costs
// microseconds per call. The transformations are exact only without overflow
// and underflow, so the stage runs only when every operand's magnitude lies in
// [2^-200, 2^200] (or is zero); then products of up to four factors stay
// normal.
class Certified {
 public:
  bool exact() const { return exact_; }
  double sum(double a, double b) {
    const double s = a + b, bv = s - a, av = s - bv;
    if ((a - av) + (b - bv) != 0) exact_ = false;
    return s;
  }
  double diff(double a, double b) { return sum(a, -b); }
  double prod(double a, double b) {
    check_range(a);
    check_range(b);
    const double p = a * b;
    if (!exact_) return p;
    double ah, al, bh, bl;
    split_veltkamp(a, ah, al);
    split_veltkamp(b, bh, bl);
    if (((ah * bh - p) + ah * bl + al * bh) + al * bl != 0) exact_ = false;
    return p;
  }

 private:
  void check_range(double v) {
    const double m = std::abs(v);
    if (m != 0 && !(m >= 0x1p-200 && m <= 0x1p200)) exact_ = false;
  }
  bool exact_ = true;
};

// Third stage of orient2d, before GMP: the determinant expanded into six
// coordinate products, each split by Dekker's two-product into a double and
// its exact rounding error, and the twelve doubles summed exactly as a
// nonoverlapping expansion (Knuth's two-sum, Shewchuk's "grow expansion" with
// zero elimination). Nothing is rounded, so the sign is exact; it decides the
// near-collinear cases with full-precision coordinates (e.g. a Steiner point
// rounded onto a slanted segment tested against the corners of its ulp box,
// which lie a subnormal away from 0 when the point is on an axis) that the
// certified stage cannot, at a fraction of GMP's cost.
// Range: each axis is first scaled by a power of two (exact) so that its
// largest magnitude is in [1/2, 1); the sign of det is unchanged (it is
// multiplied by a positive factor). The transformations are then exact when
// every nonzero scaled coordinate is at least 2^-400: products lie in
// [2^-800, 1) and every partial product of the split is a multiple of at
// least 2^-906, far from the subnormal range, and nothing can overflow.
// scale_axis returns false when that does not hold (or a value is not finite).
// scale_group does the same for any group of values that share one factor
// (floor 2^-floor_exp instead of 2^-400).
template <std::size_t N>
bool scale_group(double (&v)[N], int floor_exp) {
  double m = 0;
  for (const double x : v) m = std::max(m, std::abs(x));
  if (!std::isfinite(m)) return false;  // infinity (max skips a NaN; the loops below refuse it)
  if (m == 0) {
    for (const double x : v)
      if (x != 0) return false;  // NaN
    return true;
  }
  int e = 0;  // m = f 2^e, f in [1/2, 1) (frexp); read from the exponent bits when m is normal
  if (m >= std::numeric_limits<double>::min())
    e = static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7ff) - 1022;
  else
    std::frexp(m, &e);
  // 2^-floor_exp built from its bits (floor_exp is 250 or 400: a normal number).
  const double floor = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - floor_exp) << 52);
  // The factor 2^-e as a double when it is a normal number (almost always):
  // then x * 2^-e is the same double as ldexp(x, -e) (both exact when the
  // result is normal, both rounded once to nearest otherwise), without the
  // library call.
  const bool normal_factor = -e >= -1022 && -e <= 1023;
  const double factor = normal_factor ? std::bit_cast<double>(static_cast<std::uint64_t>(1023 - e) << 52) : 0.0;
  for (double& x : v) {
    if (x == 0) continue;
    // Exact whenever the result is at least 2^-1022. A value that would fall
    // below the floor (or to zero: a subnormal next to 1) is refused, as is NaN.
    x = normal_factor ? x * factor : std::ldexp(x, -e);
    if (!(std::abs(x) >= floor)) return false;
  }
  return true;
}
bool scale_axis(double (&v)[3]) { return scale_group(v, 400); }

// d = x - y, true when that is exact (Knuth's two-difference leaves no error;
// NaN and infinities fail).
bool exact_difference(double x, double y, double& d) {
  d = x - y;
  const double y_virtual = x - d, x_virtual = d + y_virtual;
  return (x - x_virtual) + (y_virtual - y) == 0;
}

// The exact sign of sum_k x_k y_k: the x group and the y group are each
// scaled by one power of two (the sum is multiplied by a positive factor),
// then every product is split exactly into its double and its rounding error
// and the 2N doubles are summed as an expansion. With every nonzero scaled
// factor in [2^-400, 1) the products lie in [2^-800, 1) and every partial
// product of the split is a multiple of at least 2^-906: no underflow, no
// overflow (the argument of orient2d_expansion). False when that range or
// finiteness does not hold.
template <std::size_t N>
bool sum_of_products_sign(double (&x)[N], double (&y)[N], Sign& sign) {
  if (!scale_group(x, 400) || !scale_group(y, 400)) return false;
  Expansion<2 * N> sum;
  for (std::size_t k = 0; k < N; ++k) {
    double p = 0, err = 0;
    two_product(x[k], y[k], p, err);
    sum.add(err);
    sum.add(p);
  }
  sign = sum.sign();
  return true;
}

mpq_class q(double v) { return mpq_class(v); }  // exact: every finite double is a dyadic rational

Sign orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  const mpq_class acx = q(a.x) - q(c.x), bcx = q(b.x) - q(c.x);
  const mpq_class acy = q(a.y) - q(c.y), bcy = q(b.y) - q(c.y);
  return sign_of_mpq(acx * bcy - acy * bcx);
}

mpq_class det3(const mpq_class m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

}  // namespace

Sign detail::orient2d_after_filter(Vec2 a, Vec2 b, Vec2 c) {
  {
    Certified e;
    const double ex = e.diff(a.x, c.x), fx = e.diff(b.x, c.x), ey = e.diff(a.y, c.y), fy = e.diff(b.y, c.y);
    const double exact = e.diff(e.prod(ex, fy), e.prod(ey, fx));
    if (e.exact()) return sign_of(exact);
  }
  Sign s = Sign::Zero;
  if (orient2d_expansion(a, b, c, s)) return s;
  return orient2d_exact(a, b, c);
}

bool detail::orient2d_expansion(Vec2 a, Vec2 b, Vec2 c, Sign& sign) {
  double x[3] = {a.x, b.x, c.x}, y[3] = {a.y, b.y, c.y};
  if (!scale_axis(x) || !scale_axis(y)) return false;
  // det(a - c, b - c) = (a x b) + (b x c) + (c x a), u x v = u.x v.y - u.y v.x:
  // six products, each split exactly into its double and its rounding error.
  const double factors[6][2] = {{x[0], y[1]}, {-y[0], x[1]}, {x[1], y[2]}, {-y[1], x[2]}, {x[2], y[0]}, {-y[2], x[0]}};
  Expansion<12> sum;
  for (const auto& f : factors) {
    double p = 0, err = 0;
    two_product(f[0], f[1], p, err);
    sum.add(err);
    sum.add(p);
  }
  sign = sum.sign();
  return true;
}

Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  if (Sign s{}; detail::orient3d_filter(a, b, c, d, s)) return s;
  if (Sign s = Sign::Zero; detail::orient3d_expansion(a, b, c, d, s)) return s;
  const mpq_class m[3][3] = {{q(b.x) - q(a.x), q(b.y) - q(a.y), q(b.z) - q(a.z)},
                             {q(c.x) - q(a.x), q(c.y) - q(a.y), q(c.z) - q(a.z)},
                             {q(d.x) - q(a.x), q(d.y) - q(a.y), q(d.z) - q(a.z)}};
  return sign_of_mpq(det3(m));
}

Sign orient2d_projected(Vec3 a, Vec3 b, Vec3 c, int drop) {
  auto project = [drop](Vec3 p) {
    switch (drop) {
      case 0: return Vec2{p.y, p.z};
      case 1: return Vec2{p.z, p.x};
      default: return Vec2{p.x, p.y};
    }
  };
  return orient2d(project(a), project(b), project(c));
}

namespace {

// Widens [low, top] to cover the set bits of v: v is a multiple of 2^low and
// below 2^(top + 1) in magnitude. False for subnormals, infinities, NaN.
bool note_bits(double v, int& low, int& top) {
  if (v == 0) return true;
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const int e = static_cast<int>((bits >> 52) & 0x7FF);
  if (e == 0 || e == 0x7FF) return false;
  const std::uint64_t mantissa = (bits & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
  low = std::min(low, e - 1075 + std::countr_zero(mantissa));
  top = std::max(top, e - 1023);
  return true;
}

}  // namespace

bool detail::incircle_small_integer(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Sign& sign) {
  double v[6];
  if (!exact_difference(a.x, d.x, v[0]) || !exact_difference(a.y, d.y, v[1]) || !exact_difference(b.x, d.x, v[2]) ||
      !exact_difference(b.y, d.y, v[3]) || !exact_difference(c.x, d.x, v[4]) || !exact_difference(c.y, d.y, v[5]))
    return false;
  int low = std::numeric_limits<int>::max(), top = std::numeric_limits<int>::min();
  for (const double x : v)
    if (!note_bits(x, low, top)) return false;
  if (top < low) {  // every difference is zero: four equal points
    sign = Sign::Zero;
    return true;
  }
  // v[i] = k_i 2^low with |k_i| < 2^kBits; the range keeps 2^(4 low) and the
  // largest value far from underflow and overflow.
  constexpr int kBits = 12;
  if (top + 1 - low > kBits || low < -200 || top > 200) return false;
  const double ax = v[0], ay = v[1], bx = v[2], by = v[3], cx = v[4], cy = v[5];
  const double al = ax * ax + ay * ay, bl = bx * bx + by * by, cl = cx * cx + cy * cy;
  sign = sign_of(al * (bx * cy - by * cx) + bl * (cx * ay - cy * ax) + cl * (ax * by - ay * bx));
  return true;
}

Sign detail::incircle_after_filter(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (Sign s = Sign::Zero; incircle_small_integer(a, b, c, d, s)) return s;
  {
    Certified e;
    const double ax = e.diff(a.x, d.x), ay = e.diff(a.y, d.y), bx = e.diff(b.x, d.x), by = e.diff(b.y, d.y);
    const double cx = e.diff(c.x, d.x), cy = e.diff(c.y, d.y);
    const double al = e.sum(e.prod(ax, ax), e.prod(ay, ay)), bl = e.sum(e.prod(bx, bx), e.prod(by, by));
    const double cl = e.sum(e.prod(cx, cx), e.prod(cy, cy));
    const double t1 = e.prod(al, e.diff(e.prod(bx, cy), e.prod(by, cx)));
    const double t2 = e.prod(bl, e.diff(e.prod(cx, ay), e.prod(cy, ax)));
    const double t3 = e.prod(cl, e.diff(e.prod(ax, by), e.prod(ay, bx)));
    const double exact = e.sum(e.sum(t1, t2), t3);
    if (e.exact()) return sign_of(exact);
  }
  const mpq_class ax = q(a.x) - q(d.x), ay = q(a.y) - q(d.y), bx = q(b.x) - q(d.x), by = q(b.y) - q(d.y);
  const mpq_class cx = q(c.x) - q(d.x), cy = q(c.y) - q(d.y);
  const mpq_class al = ax * ax + ay * ay, bl = bx * bx + by * by, cl = cx * cx + cy * cy;
  return sign_of_mpq(al * (bx * cy - by * cx) + bl * (cx * ay - cy * ax) + cl * (ax * by - ay * bx));
}

Sign insphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  // Rows are p - e lifted by |p - e|^2; for positively oriented abcd the 4x4
  // determinant [a-e, |a-e|^2; ...] is negative when e is inside, so the
  // result is negated to make "inside" Positive.
  const Vec3 p[4] = {a - e, b - e, c - e, d - e};
  double lift[4];
  for (int i = 0; i < 4; ++i) lift[i] = dot(p[i], p[i]);
  // Expand along the lift column: det = sum_i (-1)^(i+3) lift_i * minor_i.
  auto minor3 = [&](int skip, bool absolute) {
    int r[3], k = 0;
    for (int i = 0; i < 4; ++i)
      if (i != skip) r[k++] = i;
    const Vec3 u = p[r[0]], v = p[r[1]], w = p[r[2]];
    if (!absolute) return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
    return std::abs(u.x) * (std::abs(v.y * w.z) + std::abs(v.z * w.y)) +
           std::abs(u.y) * (std::abs(v.x * w.z) + std::abs(v.z * w.x)) +
           std::abs(u.z) * (std::abs(v.x * w.y) + std::abs(v.y * w.x));
  };
  double det = 0, permanent = 0;
  for (int i = 0; i < 4; ++i) {
    const double s = (i % 2 == 0) ? -1.0 : 1.0;  // (-1)^(i+3) with 0-based i
    det += s * lift[i] * minor3(i, false);
    permanent += lift[i] * minor3(i, true);
  }
  const auto no_tiny = [&] {
    return std::all_of(std::begin(p), std::end(p), [](Vec3 v) { return detail::no_tiny_factor(v.x, v.y, v.z); });
  };
  if (Sign s{}; detail::filtered_sign(det, permanent, 64, s, no_tiny)) return -s;
  mpq_class pe[4][3], lq[4];
  const Vec3 src[4] = {a, b, c, d};
  for (int i = 0; i < 4; ++i) {
    pe[i][0] = q(src[i].x) - q(e.x);
    pe[i][1] = q(src[i].y) - q(e.y);
    pe[i][2] = q(src[i].z) - q(e.z);
    lq[i] = pe[i][0] * pe[i][0] + pe[i][1] * pe[i][1] + pe[i][2] * pe[i][2];
  }
  mpq_class exact = 0;
  for (int i = 0; i < 4; ++i) {
    mpq_class m[3][3];
    for (int r = 0, k = 0; r < 4; ++r) {
      if (r == i) continue;
      for (int j = 0; j < 3; ++j) m[k][j] = pe[r][j];
      ++k;
    }
    const mpq_class term = lq[i] * det3(m);
    if (i % 2 == 0)
      exact -= term;
    else
      exact += term;
  }
  return -sign_of_mpq(exact);
}

namespace {

// orient3d's expansion stage when a difference b - a, c - a or d - a is not
// exact (full-precision points near a slanted facet plane: FacetPlane::settle
// and within_ulp_of_plane): multilinearity in the rows gives
// det(b - a, c - a, d - a) = det(b, c, d) - det(a, c, d) - det(b, a, d) - det(b, c, a)
// (the terms with two rows a vanish), 24 triple products of raw coordinates,
// each with one x, one y and one z, so each axis of the four points is scaled
// by one power of two (sign unchanged) and the range rule of
// add_triple_product applies (nonzero scaled values in [2^-250, 1)). False
// outside that range (GMP decides).
bool orient3d_raw_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign& sign) {
  double x[4] = {a.x, b.x, c.x, d.x}, y[4] = {a.y, b.y, c.y, d.y}, z[4] = {a.z, b.z, c.z, d.z};
  if (!scale_group(x, 250) || !scale_group(y, 250) || !scale_group(z, 250)) return false;
  Expansion<96> sum;
  // + det(rows p, q, r) (or - with negate), rows named by index 0..3 = a..d:
  // det = px (qy rz - qz ry) - py (qx rz - qz rx) + pz (qx ry - qy rx).
  const auto add_det = [&](int p, int q, int r, bool negate) {
    const double m = negate ? -1.0 : 1.0;  // negating a factor is exact
    add_triple_product(sum, m * x[p], y[q], z[r]);
    add_triple_product(sum, -m * x[p], z[q], y[r]);
    add_triple_product(sum, -m * y[p], x[q], z[r]);
    add_triple_product(sum, m * y[p], z[q], x[r]);
    add_triple_product(sum, m * z[p], x[q], y[r]);
    add_triple_product(sum, -m * z[p], y[q], x[r]);
  };
  add_det(1, 2, 3, false);  // det(b, c, d)
  add_det(0, 2, 3, true);   // - det(a, c, d)
  add_det(1, 0, 3, true);   // - det(b, a, d)
  add_det(1, 2, 0, true);   // - det(b, c, a)
  sign = sum.sign();
  return true;
}

}  // namespace

bool detail::orient3d_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign& sign) {
  // Columns of det(u, v, w), u = b - a, v = c - a, w = d - a; every term of
  // the determinant takes one entry from each column, so scaling a column
  // by a power of two scales the determinant by it (sign unchanged).
  double x[3], y[3], z[3];
  if (!exact_difference(b.x, a.x, x[0]) || !exact_difference(c.x, a.x, x[1]) || !exact_difference(d.x, a.x, x[2]) ||
      !exact_difference(b.y, a.y, y[0]) || !exact_difference(c.y, a.y, y[1]) || !exact_difference(d.y, a.y, y[2]) ||
      !exact_difference(b.z, a.z, z[0]) || !exact_difference(c.z, a.z, z[1]) || !exact_difference(d.z, a.z, z[2]))
    return orient3d_raw_expansion(a, b, c, d, sign);
  if (!scale_group(x, 250) || !scale_group(y, 250) || !scale_group(z, 250)) return false;
  // det = ux (vy wz - vz wy) - uy (vx wz - vz wx) + uz (vx wy - vy wx).
  Expansion<24> sum;
  add_triple_product(sum, x[0], y[1], z[2]);
  add_triple_product(sum, -x[0], z[1], y[2]);
  add_triple_product(sum, -y[0], x[1], z[2]);
  add_triple_product(sum, y[0], z[1], x[2]);
  add_triple_product(sum, z[0], x[1], y[2]);
  add_triple_product(sum, -z[0], y[1], x[2]);
  sign = sum.sign();
  return true;
}

bool detail::dot_sign_expansion(Vec2 a, Vec2 b, Vec2 c, Sign& sign) {
  {
    double u[2], v[2];
    if (exact_difference(b.x, a.x, u[0]) && exact_difference(b.y, a.y, u[1]) && exact_difference(c.x, a.x, v[0]) &&
        exact_difference(c.y, a.y, v[1]))
      return sum_of_products_sign(u, v, sign);
  }
  // (b - a) . (c - a) = sum_i b_i c_i - b_i a_i - a_i c_i + a_i a_i.
  double x[8] = {b.x, -b.x, -a.x, a.x, b.y, -b.y, -a.y, a.y};
  double y[8] = {c.x, a.x, c.x, a.x, c.y, a.y, c.y, a.y};
  return sum_of_products_sign(x, y, sign);
}

bool detail::dot_sign_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign& sign) {
  {
    double u[3], v[3];
    if (exact_difference(b.x, a.x, u[0]) && exact_difference(b.y, a.y, u[1]) && exact_difference(b.z, a.z, u[2]) &&
        exact_difference(d.x, c.x, v[0]) && exact_difference(d.y, c.y, v[1]) && exact_difference(d.z, c.z, v[2]))
      return sum_of_products_sign(u, v, sign);
  }
  // (b - a) . (d - c) = sum_i b_i d_i - b_i c_i - a_i d_i + a_i c_i.
  double x[12] = {b.x, -b.x, -a.x, a.x, b.y, -b.y, -a.y, a.y, b.z, -b.z, -a.z, a.z};
  double y[12] = {d.x, c.x, d.x, c.x, d.y, c.y, d.y, c.y, d.z, c.z, d.z, c.z};
  return sum_of_products_sign(x, y, sign);
}

Sign detail::dot_sign_after_filter(Vec2 a, Vec2 b, Vec2 c) {
  if (Sign s = Sign::Zero; dot_sign_expansion(a, b, c, s)) return s;
  return sign_of_mpq((q(b.x) - q(a.x)) * (q(c.x) - q(a.x)) + (q(b.y) - q(a.y)) * (q(c.y) - q(a.y)));
}

Sign detail::dot_sign_after_filter(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  {
    // The certified stage first (as orient2d's): the same expression with every
    // operation checked exact. It decides the exact right angles of grid
    // tetrahedra (differences and products of dyadic corners with few bits, a
    // determinant of exactly 0 that the filter cannot decide) at a fifth of the
    // expansion stage's cost; the quality fields test twelve angles per
    // tetrahedron.
    Certified e;
    const double ux = e.diff(b.x, a.x), uy = e.diff(b.y, a.y), uz = e.diff(b.z, a.z);
    const double vx = e.diff(d.x, c.x), vy = e.diff(d.y, c.y), vz = e.diff(d.z, c.z);
    const double exact = e.sum(e.sum(e.prod(ux, vx), e.prod(uy, vy)), e.prod(uz, vz));
    if (e.exact()) return sign_of(exact);
  }
  if (Sign s = Sign::Zero; dot_sign_expansion(a, b, c, d, s)) return s;
  return sign_of_mpq((q(b.x) - q(a.x)) * (q(d.x) - q(c.x)) + (q(b.y) - q(a.y)) * (q(d.y) - q(c.y)) +
                     (q(b.z) - q(a.z)) * (q(d.z) - q(c.z)));
}

}  // namespace pqmesh
