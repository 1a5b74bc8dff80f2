#pragma once
// orient3d's double filter and the error-free building blocks of the exact
// expansion stages (predicates.cpp, plane_side.cpp): Dekker's product with
// Veltkamp's split, triple products as four doubles, and a growing sum of
// doubles held exactly (Shewchuk's "grow expansion" with zero elimination).
// Internal to src/predicates; each function states the range in which it is
// exact.
#include <cmath>

#include "pqmesh/vec.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::detail {

// orient3d's double filter (shared by orient3d and PlaneSide):
// the determinant det(b - a, c - a, d - a) in double with the error bound 16
// eps times its permanent. True with the sign when that decides.
inline bool orient3d_filter(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Sign& sign) {
  const double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  const double m1 = cy * dz - cz * dy, m2 = cx * dz - cz * dx, m3 = cx * dy - cy * dx;
  const double det = bx * m1 - by * m2 + bz * m3;
  const double permanent = std::abs(bx) * (std::abs(cy * dz) + std::abs(cz * dy)) +
                           std::abs(by) * (std::abs(cx * dz) + std::abs(cz * dx)) +
                           std::abs(bz) * (std::abs(cx * dy) + std::abs(cy * dx));
  return filtered_sign(det, permanent, 16, sign, [&] { return no_tiny_factor(bx, by, bz, cx, cy, cz, dx, dy, dz); });
}

// Veltkamp's split: hi + lo == a, each with at most 26 significant bits
// (exact unless 2^27 a overflows).
inline void split_veltkamp(double a, double& hi, double& lo) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// p + err == a * b exactly (no overflow or underflow).
inline void two_product(double a, double b, double& p, double& err) {
  p = a * b;
  double ah, al, bh, bl;
  split_veltkamp(a, ah, al);
  split_veltkamp(b, bh, bl);
  err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

// Three products a b c, each exact as four doubles p1 + e1 + p2 + e2 (a b =
// p + e, p c = p1 + e1, e c = p2 + e2), added to `sum`. Exact when every
// nonzero factor lies in [2^-250, 1): every partial value is then a multiple
// of at least 2^-909 and below 1 (orient3d_expansion).
template <class Sum>
void add_triple_product(Sum& sum, double a, double b, double c) {
  double p = 0, e = 0, p1 = 0, e1 = 0, p2 = 0, e2 = 0;
  two_product(a, b, p, e);
  two_product(p, c, p1, e1);
  two_product(e, c, p2, e2);
  sum.add(e2);
  sum.add(p2);
  sum.add(e1);
  sum.add(p1);
}

// A sum of doubles held exactly: components nonoverlapping, by increasing
// magnitude, zeros removed; so the sign of the sum is that of the last one.
template <int N>
class Expansion {
 public:
  void add(double b) {  // adding a double adds at most one component
    double q = b;
    int m = 0;
    for (int i = 0; i < n_; ++i) {
      const double s = q + c_[i];  // two-sum: s + t == q + c_[i] exactly
      const double bv = s - q, av = s - bv;
      const double t = (q - av) + (c_[i] - bv);
      if (t != 0) c_[m++] = t;
      q = s;
    }
    if (q != 0 || m == 0) c_[m++] = q;
    n_ = m;
  }
  Sign sign() const { return n_ == 0 ? Sign::Zero : sign_of(c_[n_ - 1]); }
  int size() const { return n_; }
  double operator[](int i) const { return c_[i]; }

 private:
  double c_[N] = {};
  int n_ = 0;
};

// Shorter components with the same exact sum as `e` (Shewchuk's compression:
// a pass from the largest component down merging each into a running sum,
// then a pass back up). Every step is Knuth's two-sum, which is exact for
// any two finite doubles, so sum(out) == sum(e) exactly whatever the input;
// the result only feeds Expansion::add, which does not rely on its
// ordering. Returns the number of components written to `out` (at most
// e.size(), zeros removed).
template <int N>
int compress(const Expansion<N>& e, double (&out)[N]) {
  const int n = e.size();
  if (n == 0) return 0;
  const auto two_sum = [](double a, double b, double& s, double& t) {
    s = a + b;
    const double bv = s - a, av = s - bv;
    t = (a - av) + (b - bv);
  };
  double g[N];
  int bottom = n - 1;
  double q = e[n - 1];
  for (int i = n - 2; i >= 0; --i) {
    double s = 0, t = 0;
    two_sum(q, e[i], s, t);
    if (t != 0) {
      g[bottom--] = s;
      q = t;
    } else {
      q = s;
    }
  }
  g[bottom] = q;
  int top = 0;
  q = g[bottom];
  for (int i = bottom + 1; i < n; ++i) {
    double s = 0, t = 0;
    two_sum(g[i], q, s, t);
    if (t != 0) out[top++] = t;
    q = s;
  }
  if (q != 0) out[top++] = q;
  return top;
}

}  // namespace pqmesh::detail
