// Stretch stage of thesis ch. 5: welding the wedges along each input edge and
// the polygon Q (§5.1.1 "Welding two spirals for an edge", Fig. 5.11, and the
// definition of Q before Theorem 25).
//
// Rotation ("rotate the first spoke N of S' ... uniformly distributing the
// angle change over all S', until the angle N makes with E is the angle of
// S'"): the run of spokes of S' from E to Z (to X', the first of the two
// Fig. 5.10 spokes, when S' is a single triangle; the whole wedge when one
// spiral is kept) gets angles phi' = phi_j / (j + 1) + phi * j / (j + 1): with j equal
// steps the first spoke ends one step off E and the j + 1 steps are equal, so
// each angle at V shrinks at most by j / (j + 1) >= 1/2 ("at most halves").
// Likewise from F. A single-spiral wedge is mapped onto
// [alpha / (m + 2), alpha (m + 1) / (m + 2)].
//
// Deviations from the thesis (each a measured necessity, see the draft):
// (1) Both ends of an input edge E rotate off it by the same angle, the
// smaller of their two thesis angles: the weld triangles of Fig. 5.11 cover a
// band along all of E, and with a large rotation at one end the edge YX
// crosses features near the middle of E that only the other end's spiral
// sees (random polygons with near-touching holes).
// (2) The thesis
// keeps the spoke lengths (L(N) = L(E)/4). Rotating a spoke of length L(E)/4
// off E by the angle of S' leaves the smallest spiral S, and in a thin spike
// the rotated first spokes of the two base corners cross each other
// (data/2d/spike_5deg: Q^c overlaps). Here every rotated spoke stays on its
// continuous spiral: its radius is recomputed at its new angle, so the wedge
// stays inside S and T and Theorem 24's separation applies. The first spoke
// then has length L(E)/4 s'^theta >= L(E) / (4e) (theta <= -1/ln s'), a
// constant factor in the analysis of Fig. 5.11 (L(YU) >= 3/4 L(E) still holds).
//
// (3) Spokes are never shorter than delta_P(V) / 16 (spoke_floor.hpp): the
// thesis's spirals can meet below the resolution of doubles
// (docs/algorithm/nosteiner2d.md "Known limits").
//
// Edge welding (Fig. 5.11): for E = V -> U with first spoke N = VY of V's
// wedge and last spoke M = UX of U's wedge, if angle(N, E) <= angle(M, E)
// the triangles are VUY and YUX (new edges YU, YX), otherwise VUX and VXY.
// dQ then runs, per input loop and vertex U in loop order, along U's rim from
// its spoke at prev(U) to its spoke at next(U), and across to the next wedge.
// All of this is floating-point construction; nothing is decided here.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "nosteiner2d/spoke_floor.hpp"
#include "improve2d/triangle_angles.hpp"
#include "nosteiner2d/stages.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh {

namespace {

// Spiral radii in S's frame: S from E (phi), T from F (alpha - phi).
struct WedgeSpirals {
  double ls0, lss, lt0, lst, alpha;
  double s_at(double phi) const { return ls0 + phi * lss; }
  double t_at(double phi) const { return lt0 + (alpha - phi) * lst; }
};

// The runs of spokes that rotate off E (from index 0) and off F (from m).
struct Runs {
  int je = 0, jf = 0;                   // E run: spokes 0 .. je; F run: jf .. m
  double span_e = 0, span_f = 0;        // their angular spans (phi of je; alpha - phi of jf)
  double default_e = 0, default_f = 0;  // the thesis's rotation angles (span / (j + 1))
};

Runs runs_of(const VertexWedge& w, double alpha) {
  Runs r;
  const int m = static_cast<int>(w.spokes.size()) - 1;
  if (w.kept != VertexWedge::Kept::Both) {
    r.je = m;
    r.jf = 0;
    r.span_e = r.span_f = alpha;
    r.default_e = r.default_f = alpha / (m + 2);
    return r;
  }
  // E side: the spokes of S' (0 .. Z = thirds_first - 1); when S' is a single
  // triangle (Z on E) the run extends to X' (Fig. 5.10's first spoke).
  r.je = w.thirds_first >= 2 ? w.thirds_first - 1 : w.thirds_first;
  // F side: T' from Y = thirds_first + 2 to m, or from X'' when T' is a single triangle.
  r.jf = (m - (w.thirds_first + 2) >= 1) ? w.thirds_first + 2 : w.thirds_first + 1;
  r.span_e = w.spokes[r.je].phi;
  r.span_f = alpha - w.spokes[r.jf].phi;
  // The angle of S' (T'): a run of j >= 1 equal triangles gives span / (j + 1);
  // a single-triangle S' (run extended to X') is capped at half its angle
  // phi_X, so that the rotated first spoke stays where S is still wide
  // (s'^angle >= e^(-1/2)).
  const int ks = w.thirds_first, kt = m - w.thirds_first - 1;  // triangles of S' and T'
  r.default_e = ks >= 2 ? r.span_e / (r.je + 1) : std::min(r.span_e, w.phi_x) / 2;
  r.default_f = kt >= 2 ? r.span_f / (m - r.jf + 1) : std::min(r.span_f, alpha - w.phi_x) / 2;
  return r;
}

// Rotate so that the first spoke makes angle te with E and the last angle tf
// with F, spreading the change uniformly over each run; rotated spokes stay
// on their continuous spiral (radius recomputed at the new angle).
void rotate_off_edges(VertexWedge& w, const WedgeSpirals& sp_, const Runs& r, double te, double tf) {
  auto& sp = w.spokes;
  const double alpha = sp_.alpha;
  const int m = static_cast<int>(sp.size()) - 1;
  if (w.kept != VertexWedge::Kept::Both) {
    const bool from_s = w.kept == VertexWedge::Kept::NextOnly;
    for (auto& s : sp) {
      s.phi = te + s.phi * (alpha - te - tf) / alpha;
      s.log_rho = from_s ? sp_.s_at(s.phi) : sp_.t_at(s.phi);
    }
    return;
  }
  for (int i = 0; i < r.je; ++i) {
    sp[i].phi = te + sp[i].phi * (r.span_e - te) / r.span_e;
    sp[i].log_rho = sp_.s_at(sp[i].phi);
  }
  for (int i = r.jf + 1; i <= m; ++i) {
    const double psi = alpha - sp[i].phi;
    sp[i].phi = alpha - (tf + psi * (r.span_f - tf) / r.span_f);
    sp[i].log_rho = sp_.t_at(sp[i].phi);
  }
}

void place_points(VertexWedge& w, Vec2 V, Vec2 next) {
  const Vec2 d = (1.0 / norm(next - V)) * (next - V);
  w.representable = true;
  for (std::size_t i = 0; i < w.spokes.size(); ++i) {
    auto& s = w.spokes[i];
    const double rho = std::exp(s.log_rho), c = std::cos(s.phi), sn = std::sin(s.phi);
    s.point = V + rho * Vec2{c * d.x - sn * d.y, sn * d.x + c * d.y};
    // Exact check of the rounded construction: each wedge triangle must keep
    // its orientation (it cannot when the spokes are below the ulp of V).
    if (s.point == V || (i > 0 && orient2d(V, w.spokes[i - 1].point, s.point) != Sign::Positive))
      w.representable = false;
  }
}

// Deviation 4 (addition): of the two diagonals of the quadrilateral V U X Y
// of Fig. 5.11, keep the thesis's choice unless the other one is valid (both
// triangles counter-clockwise, exact orient2d) and has the strictly larger
// min angle. A Lawson-type local choice: never worse than the thesis's rule.
using Pair = std::array<std::array<int, 3>, 2>;
const Pair& better_diagonal(const std::vector<Vec2>& pts, const Pair& thesis, const Pair& other) {
  auto ccw = [&](const std::array<int, 3>& t) {
    return orient2d(pts[std::size_t(t[0])], pts[std::size_t(t[1])], pts[std::size_t(t[2])]) == Sign::Positive;
  };
  auto angle = [&](const Pair& p) {
    double m = std::numbers::pi;
    for (const auto& t : p)
      m = std::min(m, detail::min_angle(pts[std::size_t(t[0])], pts[std::size_t(t[1])], pts[std::size_t(t[2])]));
    return m;
  };
  if (ccw(other[0]) && ccw(other[1]) && angle(other) > angle(thesis)) return other;
  return thesis;
}

}  // namespace

PolygonQ polygon_q(const Domain2& domain, const SteinerFreeBound& bound) {
  PolygonQ q;
  const auto& P = domain.pslg.vertices;
  q.wedges.vertices = P;
  // Pass 1: the welded wedge at every vertex and the thesis's rotation angles.
  std::vector<VertexWedge> wedges;
  std::vector<WedgeSpirals> spirals;
  std::vector<Runs> runs;
  for (std::size_t i = 0; i + 1 < bound.spirals.size(); i += 2) {
    const EmptySpiral& sn = bound.spirals[i];
    const EmptySpiral& sp = bound.spirals[i + 1];
    wedges.push_back(vertex_wedge(domain, sn, sp));
    spirals.push_back(
        {std::log(sn.length / 4), 4 * sn.log_shrink, std::log(sp.length / 4), 4 * sp.log_shrink, sn.alpha});
    runs.push_back(runs_of(wedges.back(), sn.alpha));
  }
  // Pass 2: both ends of an input edge rotate off it by the smaller of their
  // two angles (see the header comment), then raise the spokes to the floor
  // (deviation 4, spoke_floor.hpp) and place them.
  std::vector<std::vector<Vec2>> p_loops;
  for (const auto& loop : domain.loops) {
    p_loops.emplace_back();
    for (int v : loop) p_loops.back().push_back(P[std::size_t(v)]);
  }
  const PolygonDelta delta_p = polygon_delta(p_loops);
  std::vector<std::vector<int>> first_id(domain.loops.size());
  std::size_t base = 0;
  for (std::size_t l = 0; l < domain.loops.size(); ++l) {
    const auto& loop = domain.loops[l];
    const int n = static_cast<int>(loop.size());
    for (int k = 0; k < n; ++k) {
      const std::size_t i = base + k, inext = base + (k + 1) % n, iprev = base + (k + n - 1) % n;
      const double te = std::min(runs[i].default_e, runs[inext].default_f);
      const double tf = std::min(runs[i].default_f, runs[iprev].default_e);
      VertexWedge w = wedges[i];
      rotate_off_edges(w, spirals[i], runs[i], te, tf);
      detail::floor_spokes(w, std::log(detail::kSpokeFloorFraction * delta_p.vertex[l][std::size_t(k)]));
      place_points(w, P[loop[k]], P[loop[(k + 1) % n]]);
      q.representable = q.representable && w.representable;
      first_id[l].push_back(static_cast<int>(q.wedges.vertices.size()));
      const int v = loop[k];
      for (std::size_t s = 0; s < w.spokes.size(); ++s) {
        q.wedges.vertices.push_back(w.spokes[s].point);
        if (s > 0) {
          const int a = first_id[l].back() + static_cast<int>(s) - 1;
          q.wedges.triangles.push_back({v, a, a + 1});
        }
      }
      q.vertex_wedges.push_back(std::move(w));
    }
    base += static_cast<std::size_t>(n);
  }
  // Edge triangles and dQ.
  base = 0;
  for (std::size_t l = 0; l < domain.loops.size(); ++l) {
    const auto& loop = domain.loops[l];
    const int n = static_cast<int>(loop.size());
    std::vector<int> ql;
    for (int k = 0; k < n; ++k) {
      const VertexWedge& wu = q.vertex_wedges[base + k];
      const int m = static_cast<int>(wu.spokes.size()) - 1;
      for (int i = m; i >= 0; --i) ql.push_back(first_id[l][k] + i);
      // Edge E = V -> U with V = loop[k], U = loop[k + 1].
      const int kn = (k + 1) % n;
      const VertexWedge& wv = wu;
      const VertexWedge& wn = q.vertex_wedges[base + kn];
      const int v = loop[k], u = loop[kn];
      const int y = first_id[l][k];                                            // N's end (V's spoke 0)
      const int x = first_id[l][kn] + static_cast<int>(wn.spokes.size()) - 1;  // M's end (U's last spoke)
      const double angle_n = wv.spokes.front().phi;
      const double angle_m = bound.spirals[2 * (base + kn)].alpha - wn.spokes.back().phi;
      const std::array<std::array<int, 3>, 2> by_uy{{{v, u, y}, {y, u, x}}}, by_vx{{{v, u, x}, {v, x, y}}};
      const bool thesis_uy = angle_n <= angle_m;
      const auto& chosen = better_diagonal(q.wedges.vertices, thesis_uy ? by_uy : by_vx, thesis_uy ? by_vx : by_uy);
      q.wedges.triangles.push_back(chosen[0]);
      q.wedges.triangles.push_back(chosen[1]);
    }
    q.loops.push_back(std::move(ql));
    base += static_cast<std::size_t>(n);
  }
  q.min_angle = std::numbers::pi;
  for (const auto& t : q.wedges.triangles)
    q.min_angle = std::min(
        q.min_angle, detail::min_angle(q.wedges.vertices[t[0]], q.wedges.vertices[t[1]], q.wedges.vertices[t[2]]));
  return q;
}

}  // namespace pqmesh
