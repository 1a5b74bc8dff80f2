#include "predicates/plane_side.hpp"

#include <cmath>

#include "predicates/expansion.hpp"

namespace pqmesh {
namespace {

// Zero, or a finite magnitude in [2^-150, 2^150] (PlaneSide's range).
bool in_plane_range(double v) {
  const double m = std::abs(v);
  return m == 0 || (m >= 0x1p-150 && m <= 0x1p150);
}
bool in_plane_range(Vec3 p) { return in_plane_range(p.x) && in_plane_range(p.y) && in_plane_range(p.z); }

void add_product(detail::Expansion<12>& sum, double x, double y) {
  double p = 0, err = 0;
  detail::two_product(x, y, p, err);
  sum.add(err);
  sum.add(p);
}

}  // namespace

PlaneSide::PlaneSide(Vec3 a, Vec3 b, Vec3 c) : a_(a), b_(b), c_(c) {
  for (int i = 0; i < 3; ++i) normal_[static_cast<std::size_t>(i)] = orient2d_projected(a, b, c, i);
  in_range_ = in_plane_range(a) && in_plane_range(b) && in_plane_range(c);
  if (!in_range_) return;
  for (int i = 0; i < 3; ++i) {
    // Component i of N = b x c + c x a + a x b, (i, j, k) cyclic:
    // b_j c_k - b_k c_j + c_j a_k - c_k a_j + a_j b_k - a_k b_j.
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double aj = axis_coord(a, j), ak = axis_coord(a, k), bj = axis_coord(b, j), bk = axis_coord(b, k);
    const double cj = axis_coord(c, j), ck = axis_coord(c, k);
    detail::Expansion<12> sum;
    add_product(sum, bj, ck);
    add_product(sum, -bk, cj);
    add_product(sum, cj, ak);
    add_product(sum, -ck, aj);
    add_product(sum, aj, bk);
    add_product(sum, -ak, bj);
    n_len_[i] = detail::compress(sum, n_[i]);
  }
  // -K = -det(a, b, c) = -(a_x (b_y c_z - b_z c_y) - a_y (b_x c_z - b_z c_x) + a_z (b_x c_y - b_y c_x)).
  detail::Expansion<24> k;
  detail::add_triple_product(k, -a.x, b.y, c.z);
  detail::add_triple_product(k, a.x, b.z, c.y);
  detail::add_triple_product(k, a.y, b.x, c.z);
  detail::add_triple_product(k, -a.y, b.z, c.x);
  detail::add_triple_product(k, -a.z, b.x, c.y);
  detail::add_triple_product(k, a.z, b.y, c.x);
  k_len_ = detail::compress(k, minus_k_);
}

bool PlaneSide::expansion_sign(Vec3 d, Sign& sign) const {
  if (!in_range_) return false;
  // A "tiny" coordinate (below 2^-950: the ulp box corners of a point on an
  // axis plane are +-2^-1074) is left out of the sum E0 and decided by
  // magnitude: E0 is a multiple of 2^-606, so E0 != 0 means |E0| >= 2^-606,
  // while every left-out term |N_i d_i| < 2^303 2^-950 and their sum is below
  // 2^-645: the sign is E0's. When E0 == 0 and one coordinate is tiny, the
  // sign is that of N_i d_i (N_i's sign is exact, normal_); two or more:
  // orient3d decides.
  int tiny_axis = -1, tiny_count = 0;
  for (int i = 0; i < 3; ++i) {
    const double m = std::abs(axis_coord(d, i));
    if (m == 0 || (m >= 0x1p-150 && m <= 0x1p150)) continue;
    if (!(m < 0x1p-950)) return false;  // between the ranges, too large, or NaN
    tiny_axis = i;
    ++tiny_count;
  }
  // Capacity: every add grows the sum by at most one component.
  detail::Expansion<24 + 2 * 3 * 12> sum;
  for (int t = 0; t < k_len_; ++t) sum.add(minus_k_[t]);
  for (int i = 0; i < 3; ++i) {
    const double di = axis_coord(d, i);
    if (di == 0 || std::abs(di) < 0x1p-950) continue;
    for (int t = 0; t < n_len_[i]; ++t) {
      double p = 0, err = 0;
      detail::two_product(n_[i][t], di, p, err);
      sum.add(err);
      sum.add(p);
    }
  }
  const Sign e0 = sum.sign();
  if (e0 != Sign::Zero || tiny_count == 0) {
    sign = e0;
    return true;
  }
  if (tiny_count > 1) return false;
  sign = normal_[static_cast<std::size_t>(tiny_axis)] * sign_of(axis_coord(d, tiny_axis));
  return true;
}

Sign PlaneSide::operator()(Vec3 d) const {
  if (Sign s{}; detail::orient3d_filter(a_, b_, c_, d, s)) return s;
  if (Sign s = Sign::Zero; expansion_sign(d, s)) return s;
  return orient3d(a_, b_, c_, d);
}

bool PlaneSide::meets_ulp_box(Vec3 p) const {
  const double lo[3] = {next_down(p.x), next_down(p.y), next_down(p.z)};
  const double hi[3] = {next_up(p.x), next_up(p.y), next_up(p.z)};
  double up[3], down[3];
  for (int i = 0; i < 3; ++i) {
    const bool negative = normal_[static_cast<std::size_t>(i)] == Sign::Negative;
    up[i] = negative ? lo[i] : hi[i];
    down[i] = negative ? hi[i] : lo[i];
  }
  const Sign s = (*this)({up[0], up[1], up[2]});
  if (s == Sign::Zero) return true;
  return (*this)({down[0], down[1], down[2]}) != s;
}

}  // namespace pqmesh
