#pragma once
// Exact numbers of the form c0 + c1 e + c2 e^2 + c3 e^3 + c4 d + c5 d^2
// (ck rational, e and d infinitesimals with 1 >> e >> e^2 >> e^3 >> d >> d^2),
// the symbolic quantities of the outward shift of a cube (cube_components.hpp).
// Only the operations the module needs: affine combinations with rational
// factors and the exact sign, decided by the first non-zero coefficient.
// Products of two perturbed numbers never occur: every coordinate the module
// forms is affine in the shifted cube planes and the probe offsets.
#include <array>

#include <gmpxx.h>

namespace pqmesh::mv3d::detail {

enum Term : int { kOne = 0, kE1 = 1, kE2 = 2, kE3 = 3, kD1 = 4, kD2 = 5 };

struct Pert {
  std::array<mpq_class, 6> c;

  static Pert constant(double v) {
    Pert p;
    p.c[kOne] = v;
    return p;
  }
  // v + s * term  (s = +1 or -1)
  static Pert shifted(double v, int term, int s) {
    Pert p = constant(v);
    p.c[static_cast<std::size_t>(term)] = s;
    return p;
  }
  Pert& operator+=(const Pert& o) {
    for (std::size_t i = 0; i < c.size(); ++i) c[i] += o.c[i];
    return *this;
  }
  Pert& operator-=(const Pert& o) {
    for (std::size_t i = 0; i < c.size(); ++i) c[i] -= o.c[i];
    return *this;
  }
  Pert& operator*=(const mpq_class& f) {
    for (auto& x : c) x *= f;
    return *this;
  }
  friend Pert operator+(Pert a, const Pert& b) { return a += b; }
  friend Pert operator-(Pert a, const Pert& b) { return a -= b; }
  friend Pert operator*(Pert a, const mpq_class& f) { return a *= f; }
  friend Pert operator*(const mpq_class& f, Pert a) { return a *= f; }

  // -1, 0, +1: the sign of the infinitesimal-perturbed value.
  int sign() const {
    for (const auto& x : c) {
      const int s = sgn(x);
      if (s != 0) return s > 0 ? 1 : -1;
    }
    return 0;
  }
};

// sign(a - b), coefficient by coefficient (no temporaries).
inline int compare(const Pert& a, const Pert& b) {
  for (std::size_t i = 0; i < a.c.size(); ++i) {
    const int r = cmp(a.c[i], b.c[i]);
    if (r != 0) return r > 0 ? 1 : -1;
  }
  return 0;
}

}  // namespace pqmesh::mv3d::detail
