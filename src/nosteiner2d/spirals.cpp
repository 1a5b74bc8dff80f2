// Stages 3-4 of thesis ch. 5: the smallest spiral and the (smallest) optimal
// spiral (§5.1 "Smallest spiral", Theorems 20, 22, 24).
//
// Optimal spiral of a continuous spiral rho = L s^phi for the sector
// [0, omega] (Theorem 22 and the rounding before Theorem 20): the relaxed
// problem max a theta s.t. a^(1/theta) = s has a = 1/e, theta* = -1/ln s and
// value -1/(e ln s). The last spoke must lie at phi = omega, so theta is
// decreased to omega / k with k = ceil(omega / theta*) (at worst halving it)
// and a = s^theta is increased; Theorem 16's cap theta <= pi/2 gives
// k >= ceil(omega / (pi/2)) (at most four triangles when s is close to 1,
// Theorem 20's case r > 1/e). Floating point throughout: these are
// constructions of the later stages, not decisions.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "improve2d/triangle_angles.hpp"
#include "nosteiner2d/stages.hpp"

namespace pqmesh {

SmallestSpiral smallest_spiral(const EmptySpiral& empty) {
  SmallestSpiral s;
  s.length = empty.length / 4;
  s.log_shrink = 4 * empty.log_shrink;
  s.shrink = std::exp(s.log_shrink);
  return s;
}

OptimalSpiral optimal_spiral(const Domain2& domain, const EmptySpiral& empty, const SmallestSpiral& spiral,
                             double omega) {
  OptimalSpiral o;
  const double ls = spiral.log_shrink;  // <= 0
  int k = static_cast<int>(std::ceil(omega / (std::numbers::pi / 2)));
  if (ls < 0) k = std::max(k, static_cast<int>(std::ceil(omega * -ls)));  // omega / theta*
  k = std::max(k, 1);
  o.triangles = k;
  o.theta = omega / k;
  o.a = std::exp(o.theta * ls);
  o.min_angle_approx = o.a * o.theta;

  const Vec2 V = domain.pslg.vertices[empty.vertex];
  const Vec2 U = domain.pslg.vertices[empty.other];
  const Vec2 d = (1.0 / norm(U - V)) * (U - V);
  const double hand = empty.ccw ? 1.0 : -1.0;
  o.spoke_vertices.reserve(static_cast<std::size_t>(k) + 1);
  for (int i = 0; i <= k; ++i) {
    const double phi = i * o.theta, rho = spiral.length * std::exp(phi * ls);
    o.spoke_log_ratio.push_back(phi * ls);
    const double c = std::cos(phi), s = hand * std::sin(phi);
    o.spoke_vertices.push_back(V + rho * Vec2{c * d.x - s * d.y, s * d.x + c * d.y});
  }
  // All triangles are similar (Theorem 19): measure the first.
  o.min_angle = detail::min_angle(V, o.spoke_vertices[0], o.spoke_vertices[1]);
  return o;
}

}  // namespace pqmesh
