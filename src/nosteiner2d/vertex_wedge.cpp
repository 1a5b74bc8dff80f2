// Stretch stage of thesis ch. 5: welding the two smallest optimal spirals at
// a vertex (§5.1.1 "Welding two spirals at a vertex", Figs. 5.8-5.10).
//
// In S's frame (phi from E = V -> next(V)) the two smallest spirals are
//   ln rho_S(phi) = ln(L(E)/4) + phi ln s_E',   ln rho_T(phi) = ln(L(F)/4) + (alpha - phi) ln s_F'.
// D(phi) = ln rho_S - ln rho_T is linear with slope ln s_E' + ln s_F' <= 0,
// so the curves meet at most once, at X (Fig. 5.8). The wedge keeps S from E
// to X and T from X to F. If D <= 0 on [0, alpha] (X "on E") S is discarded;
// if D >= 0 (X "on F", or coincident circles) T is discarded.
//
// Then (Fig. 5.9) S' = the optimal spiral of S with last spoke VX
// (omega = phi_X), T' likewise with omega = alpha - phi_X. When phi_X is less
// than half the angle theta of S's smallest optimal spiral for the whole
// corner, S' is a single triangle; the thesis then moves X along line ZX
// (Z = second-to-last spoke of S') to X' with VX' bisecting angle YVZ
// (Y = second-to-last spoke of T'). The thesis skips this when S' is already
// within a constant factor of T'; we always apply it in that case (its proof
// covers both). Symmetrically for T'.
// Finally (Fig. 5.10) the spoke VX is replaced by two spokes of the same
// length at one and two thirds of the angle between Z and Y.
//
// Floating point throughout (constructions); no decision here depends on a
// tolerance: the case split uses the signs of D at the ends, which are
// floating values of a construction, not predicates on input coordinates.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "nosteiner2d/stages.hpp"

namespace pqmesh {

namespace {

struct Polar {
  double phi, log_rho;
};

// Spokes of the optimal spiral of (ln length, ln shrink) over [0, omega],
// mapped to S's frame by phi -> origin + sign * phi.
std::vector<Polar> spiral_spokes(double log_length, double log_shrink, double omega, double origin, double sign) {
  int k = static_cast<int>(std::ceil(omega / (std::numbers::pi / 2)));
  if (log_shrink < 0) k = std::max(k, static_cast<int>(std::ceil(omega * -log_shrink)));
  k = std::max(k, 1);
  const double theta = omega / k;
  std::vector<Polar> out;
  for (int i = 0; i <= k; ++i) out.push_back({origin + sign * i * theta, log_length + i * theta * log_shrink});
  return out;
}

double full_theta(double log_shrink, double alpha) {
  int k = static_cast<int>(std::ceil(alpha / (std::numbers::pi / 2)));
  if (log_shrink < 0) k = std::max(k, static_cast<int>(std::ceil(alpha * -log_shrink)));
  return alpha / std::max(k, 1);
}

// Smallest angle of the triangle (V, p, q) from polar data (scale-free).
double polar_min_angle(Polar p, Polar q) {
  const double delta = std::abs(q.phi - p.phi);
  const double a = std::exp(q.log_rho - p.log_rho);  // |Vq| / |Vp|
  const double at_p = std::atan2(a * std::sin(delta), 1 - a * std::cos(delta));
  const double at_q = std::numbers::pi - delta - at_p;
  return std::min({delta, at_p, at_q});
}

// The point of line (z, x) on the ray at angle phi (polar line equation);
// x itself when the ray misses the line (not expected: phi lies between z's
// and the far spoke's angles, less than pi apart).
Polar on_line(Polar z, Polar x, double phi) {
  // rho(phi) = rz rx sin(px - pz) / (rz sin(phi - pz) + rx sin(px - phi)); with
  // u = rx / rz: rho = rz u sin(px - pz) / (sin(phi - pz) + u sin(px - phi)).
  const double u = std::exp(x.log_rho - z.log_rho);
  const double num = u * std::sin(x.phi - z.phi);
  const double den = std::sin(phi - z.phi) + u * std::sin(x.phi - phi);
  if (!(num / den > 0) || !std::isfinite(num / den)) return x;
  return {phi, z.log_rho + std::log(num / den)};
}

}  // namespace

VertexWedge vertex_wedge(const Domain2& domain, const EmptySpiral& next_side, const EmptySpiral& prev_side) {
  VertexWedge w;
  w.vertex = next_side.vertex;
  const double alpha = next_side.alpha;
  const double lS0 = std::log(next_side.length / 4), lsS = 4 * next_side.log_shrink;
  const double lT0 = std::log(prev_side.length / 4), lsT = 4 * prev_side.log_shrink;
  auto D = [&](double phi) { return (lS0 + phi * lsS) - (lT0 + (alpha - phi) * lsT); };
  const double d0 = D(0), d1 = D(alpha);

  std::vector<Polar> spokes;
  if (d1 >= 0) {  // S outside T on the whole corner (or coincident circles)
    w.kept = VertexWedge::Kept::NextOnly;
    spokes = spiral_spokes(lS0, lsS, alpha, 0, 1);
  } else if (d0 <= 0) {
    w.kept = VertexWedge::Kept::PrevOnly;
    spokes = spiral_spokes(lT0, lsT, alpha, alpha, -1);
    std::reverse(spokes.begin(), spokes.end());
  } else {
    w.kept = VertexWedge::Kept::Both;
    w.phi_x = d0 / -(lsS + lsT);
    std::vector<Polar> s = spiral_spokes(lS0, lsS, w.phi_x, 0, 1);
    std::vector<Polar> t = spiral_spokes(lT0, lsT, alpha - w.phi_x, alpha, -1);  // from F towards X
    Polar x = s.back();
    Polar z = s[s.size() - 2], y = t[t.size() - 2];
    if (w.phi_x < full_theta(lsS, alpha) / 2) {
      w.small_side_fixed = true;
      x = on_line(z, x, 0.5 * (z.phi + y.phi));
    } else if (alpha - w.phi_x < full_theta(lsT, alpha) / 2) {
      w.small_side_fixed = true;
      x = on_line(y, x, 0.5 * (z.phi + y.phi));
    }
    w.phi_x_moved = x.phi;
    w.log_rho_x_moved = x.log_rho;
    // Fig. 5.10: VX becomes two spokes of the same length at thirds of ZVY.
    // "The same length as the old spoke VX": after the fix that is |VX'|;
    // these two spokes may then leave the envelope of S and T by a constant
    // factor (the thesis claims containment for the fix, not for this step).
    s.pop_back();
    t.pop_back();
    spokes = s;
    w.thirds_first = static_cast<int>(spokes.size());
    const double delta = y.phi - z.phi;
    spokes.push_back({z.phi + delta / 3, x.log_rho});
    spokes.push_back({z.phi + 2 * delta / 3, x.log_rho});
    for (auto it = t.rbegin(); it != t.rend(); ++it) spokes.push_back(*it);
  }

  const Vec2 V = domain.pslg.vertices[w.vertex];
  const Vec2 U = domain.pslg.vertices[next_side.other];
  const Vec2 d = (1.0 / norm(U - V)) * (U - V);
  w.min_angle = std::numbers::pi;
  for (std::size_t i = 0; i < spokes.size(); ++i) {
    const double rho = std::exp(spokes[i].log_rho), c = std::cos(spokes[i].phi), sn = std::sin(spokes[i].phi);
    const Vec2 p = V + rho * Vec2{c * d.x - sn * d.y, sn * d.x + c * d.y};
    w.spokes.push_back({spokes[i].phi, spokes[i].log_rho, p});
    if (p == V || (i > 0 && p == w.spokes[i - 1].point)) w.representable = false;
    if (i > 0) w.min_angle = std::min(w.min_angle, polar_min_angle(spokes[i - 1], spokes[i]));
  }
  return w;
}

}  // namespace pqmesh
