// Polar frame of a (vertex, edge) pair; see spiral_frame.hpp.
#include "nosteiner2d/spiral_frame.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace pqmesh::detail {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
}

SpiralFrame make_frame(const Domain2& domain, int loop, int k, bool ccw) {
  const auto& ids = domain.loops[loop];
  const int n = static_cast<int>(ids.size());
  const auto& P = domain.pslg.vertices;
  SpiralFrame fr;
  fr.ccw = ccw;
  fr.v = ids[k];
  const int next = ids[(k + 1) % n], prev = ids[(k + n - 1) % n];
  fr.u = ccw ? next : prev;
  fr.f = ccw ? prev : next;
  fr.V = P[fr.v];
  fr.U = P[fr.u];
  fr.F = P[fr.f];
  fr.length = norm(fr.U - fr.V);
  fr.turn = fr.oriented(fr.V, fr.U, fr.F);
  const Vec2 d = fr.U - fr.V, e = fr.F - fr.V;
  double a = std::atan2((ccw ? 1.0 : -1.0) * cross(d, e), dot(d, e));
  // Make the floating value agree with the exact turn (it can only disagree
  // by rounding when alpha is within rounding of 0, pi or 2 pi; the sign of
  // the dot product says which).
  const bool forward = dot(d, e) > 0;
  if (fr.turn == Sign::Zero) {
    a = std::numbers::pi;
  } else if (fr.turn == Sign::Positive) {
    if (!(a > 0)) a = forward ? std::numeric_limits<double>::min() : std::numbers::pi;
  } else {
    if (a <= 0) a += kTwoPi;
    if (a < std::numbers::pi) a = forward ? std::nextafter(kTwoPi, 0.0) : std::numbers::pi;
  }
  fr.alpha = a;
  return fr;
}

bool SpiralFrame::in_sector(Vec2 w) const {
  const Sign s1 = oriented(V, U, w);
  const Sign s2 = oriented(V, w, F);
  if (turn == Sign::Positive) return s1 != Sign::Negative && s2 != Sign::Negative;
  if (turn == Sign::Zero) return s1 != Sign::Negative;
  // Reflex: the exterior is the open convex sector from F to E (turning the
  // frame's way); the closed interior sector is its complement.
  const bool exterior = oriented(V, F, w) == Sign::Positive && oriented(V, w, U) == Sign::Positive;
  return !exterior;
}

double SpiralFrame::phi(Vec2 w) const {
  const Vec2 d = U - V, x = w - V;
  double a = std::atan2((ccw ? 1.0 : -1.0) * cross(d, x), dot(d, x));
  if (a < 0) a += kTwoPi;
  if (a > alpha) a = (a - alpha < kTwoPi - a) ? alpha : 0.0;
  return a;
}

Vec2 SpiralFrame::point_at(double rho, double angle) const {
  const Vec2 d = (1.0 / length) * (U - V);
  const double c = std::cos(angle), s = (ccw ? 1.0 : -1.0) * std::sin(angle);
  return V + rho * Vec2{c * d.x - s * d.y, s * d.x + c * d.y};
}

}  // namespace pqmesh::detail
