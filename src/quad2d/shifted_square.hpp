#pragma once
// Exact geometry of P edges against the shifted square C_e of
// components2d.hpp: side crossings, their order along ∂C_e, the corner
// parity and the ray of the 2D tether (components2d.cpp outline, steps 1, 3
// and 4).
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"
#include "quad2d/components2d.hpp"

namespace pqmesh::quad2d::detail {

// The square C as bounds; the shift to C_e is symbolic (components2d.hpp).
struct Box {
  double xlo, ylo, xhi, yhi;
};

inline Box box_of(const Square& s) { return {s.lo.x, s.lo.y, s.lo.x + s.side, s.lo.y + s.side}; }

// Inside the closed half-plane of side s of the SHIFTED square (side lines
// y = ylo - e^2, x = xhi + e, y = yhi + e^2, x = xlo - e): exact comparisons.
inline bool in_half(Vec2 p, int s, const Box& b) {
  switch (s) {
    case 0: return p.y >= b.ylo;
    case 1: return p.x <= b.xhi;
    case 2: return p.y <= b.yhi;
    default: return p.x >= b.xlo;
  }
}

// In the shifted square (all four half-planes).
inline bool inside(Vec2 p, const Box& b) { return in_half(p, 0, b) && in_half(p, 1, b) && in_half(p, 2, b) && in_half(p, 3, b); }

// The endpoints of a directed loop edge.
struct EdgeGeom {
  Vec2 a, c;
};

inline EdgeGeom geom(const Domain2& d, LoopEdge e) {
  const auto& loop = d.loops[static_cast<std::size_t>(e.loop)];
  const std::size_t n = loop.size();
  const std::size_t i = static_cast<std::size_t>(e.index);
  return {d.pslg.vertices[static_cast<std::size_t>(loop[i])], d.pslg.vertices[static_cast<std::size_t>(loop[(i + 1) % n])]};
}

// The PSLG segment of a loop edge.
inline int segment_id(const Domain2& d, LoopEdge e) {
  return d.loop_segments[static_cast<std::size_t>(e.loop)][static_cast<std::size_t>(e.index)];
}

// Order of loop edges: by loop, then index.
inline bool less_edge(LoopEdge x, LoopEdge y) { return x.loop != y.loop ? x.loop < y.loop : x.index < y.index; }

// The crossings of one edge with the sides of the shifted square.
struct EdgeCrossings {
  int count = 0;
  std::array<int, 2> side{};
  std::array<int, 2> dir{};  // +1 entry, -1 exit; entry first when both
};

// Crossings of the directed edge a -> c with the sides of the shifted square
// (at most two; the entry first).
EdgeCrossings crossings_of(Vec2 a, Vec2 c, const Box& b);

// Does the closed segment ac meet the shifted square?
bool meets(Vec2 a, Vec2 c, const Box& b);

// Crossing of the directed edge with the side line, as a parameter along ∂C
// (a construction for reports; clamped into the side).
double crossing_t(Vec2 a, Vec2 c, const Box& b, int s);

// Compare the crossings of segments 1 and 2 with the line at c0 + sgn * eps
// (eps infinitesimal): the value at c0 first (a floating-point filter with a
// proven error bound, else GMP rationals), then the derivative (exact).
int cmp_on_line(Vec2 a1, Vec2 c1, Vec2 a2, Vec2 c2, bool horizontal, double c0, int sgn);

// Crossing parity of the ray from the perturbed lo corner (xlo - e, ylo - e^2)
// in +x with every edge of P: is that corner inside P?
bool corner_in_domain(const Domain2& d, const Box& b);

// The first edge hit by the ray {(x, p.y + d) : x > p.x}, d infinitesimal
// (d << e^2), before it leaves the shifted square through the right side.
// Edges of loop skip_loop are ignored.
std::optional<std::size_t> first_hit(const Domain2& d, const Box& b, Vec2 p,
                                     const std::vector<std::pair<LoopEdge, int>>& edges, int skip_loop);

// The first crossing counter-clockwise after the point (xhi + e, p.y + d) on
// the right side (sorted crossings; wraps to 0).
std::size_t crossing_after_right_point(const Domain2& d, const Box& b, Vec2 p, const std::vector<Crossing>& crossings);

}  // namespace pqmesh::quad2d::detail
