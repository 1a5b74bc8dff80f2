#include "predicates/predicates.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <optional>

namespace pqmesh {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2^-52

// Below this permanent the error analysis could be spoiled by underflow, so
// the exact path is taken unconditionally.
constexpr double kTinyPermanent = 1e-280;

// The error-bound constants are deliberately generous (a few times the bounds
// that a careful rounding analysis gives for these expression trees): a too
// large bound only sends more cases to the exact path, never a wrong sign.
// Returns the certain sign, or nullopt when the exact path must decide.
std::optional<Sign> filter(double det, double permanent, double factor) {
  if (permanent == 0) return Sign::Zero;  // every term is exactly zero
  if (permanent <= kTinyPermanent) return std::nullopt;
  const double bound = factor * kEps * permanent;
  if (det > bound) return Sign::Positive;
  if (-det > bound) return Sign::Negative;
  return std::nullopt;
}

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
    split(a, ah, al);
    split(b, bh, bl);
    if (((ah * bh - p) + ah * bl + al * bh) + al * bl != 0) exact_ = false;
    return p;
  }

 private:
  void check_range(double v) {
    const double m = std::abs(v);
    if (m != 0 && !(m >= 0x1p-200 && m <= 0x1p200)) exact_ = false;
  }
  static void split(double a, double& hi, double& lo) {
    const double c = 134217729.0 * a;  // 2^27 + 1
    const double big = c - a;
    hi = c - big;
    lo = a - hi;
  }
  bool exact_ = true;
};

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

Sign orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double acx = a.x - c.x, bcx = b.x - c.x, acy = a.y - c.y, bcy = b.y - c.y;
  const double l = acx * bcy, r = acy * bcx;
  const double det = l - r;
  const double permanent = std::abs(l) + std::abs(r);
  if (const auto s = filter(det, permanent, 8)) return *s;
  Certified e;
  const double ex = e.diff(a.x, c.x), fx = e.diff(b.x, c.x), ey = e.diff(a.y, c.y), fy = e.diff(b.y, c.y);
  const double exact = e.diff(e.prod(ex, fy), e.prod(ey, fx));
  if (e.exact()) return sign_of(exact);
  return orient2d_exact(a, b, c);
}

Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  const double m1 = cy * dz - cz * dy, m2 = cx * dz - cz * dx, m3 = cx * dy - cy * dx;
  const double det = bx * m1 - by * m2 + bz * m3;
  const double permanent = std::abs(bx) * (std::abs(cy * dz) + std::abs(cz * dy)) +
                           std::abs(by) * (std::abs(cx * dz) + std::abs(cz * dx)) +
                           std::abs(bz) * (std::abs(cx * dy) + std::abs(cy * dx));
  if (const auto s = filter(det, permanent, 16)) return *s;
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

Sign incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdx * cdy - bdy * cdx) + blift * (cdx * ady - cdy * adx) + clift * (adx * bdy - ady * bdx);
  const double permanent = alift * (std::abs(bdx * cdy) + std::abs(bdy * cdx)) +
                           blift * (std::abs(cdx * ady) + std::abs(cdy * adx)) +
                           clift * (std::abs(adx * bdy) + std::abs(ady * bdx));
  if (const auto s = filter(det, permanent, 32)) return *s;
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
    if (!absolute)
      return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
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
  if (const auto s = filter(det, permanent, 64)) return -*s;
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
    if (i % 2 == 0) exact -= term;
    else exact += term;
  }
  return -sign_of_mpq(exact);
}

Sign dot_sign(Vec2 a, Vec2 b, Vec2 c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  const double l = ux * vx, r = uy * vy;
  const double det = l + r, permanent = std::abs(l) + std::abs(r);
  if (const auto s = filter(det, permanent, 8)) return *s;
  return sign_of_mpq((q(b.x) - q(a.x)) * (q(c.x) - q(a.x)) + (q(b.y) - q(a.y)) * (q(c.y) - q(a.y)));
}

Sign dot_sign(Vec3 a, Vec3 b, Vec3 c) { return dot_sign(a, b, a, c); }

Sign dot_sign(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = d.x - c.x, vy = d.y - c.y, vz = d.z - c.z;
  const double det = ux * vx + uy * vy + uz * vz;
  const double permanent = std::abs(ux * vx) + std::abs(uy * vy) + std::abs(uz * vz);
  if (const auto s = filter(det, permanent, 8)) return *s;
  return sign_of_mpq((q(b.x) - q(a.x)) * (q(d.x) - q(c.x)) + (q(b.y) - q(a.y)) * (q(d.y) - q(c.y)) +
                     (q(b.z) - q(a.z)) * (q(d.z) - q(c.z)));
}

}  // namespace pqmesh
