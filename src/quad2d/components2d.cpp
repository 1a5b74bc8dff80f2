// Components of P ∩ C (thesis §4.1.6 in 2D). See components2d.hpp for the
// perturbation rule. Outline:
//   1. every P edge is clipped to the shifted square; a crossing of a P edge
//      with a side is a proper segment crossing (exact tests, below);
//   2. pieces of ∂P inside C are linked into chains, entry crossing -> inside
//      vertices -> exit crossing, following the loop direction (interior of P
//      on the left);
//   3. crossings are sorted counter-clockwise along ∂C (exact); after an exit
//      the next crossing counter-clockwise is an entry (the arc between them
//      lies in P), which links the chains into closed counter-clockwise cycles,
//      one per component (each component of P ∩ C that meets ∂C has exactly
//      one outer cycle; its holes are P loops lying inside C);
//   4. P loops lying entirely inside C are attached to the component found by
//      shooting a ray in +x from their rightmost vertex (the 2D tether of
//      §4.1.6) to the first hit: a chain edge, another inside loop (recurse;
//      acyclic because x increases strictly), or the right side of C (then the
//      arc of ∂C containing that point decides).
#include "quad2d/components2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <gmpxx.h>

#include "pqmesh/errors.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::quad2d {
namespace {

struct Box {
  double xlo, ylo, xhi, yhi;
};

Box box_of(const Square& s) { return {s.lo.x, s.lo.y, s.lo.x + s.side, s.lo.y + s.side}; }

// Inside the closed half-plane of side s of the SHIFTED square (side lines
// y = ylo - e^2, x = xhi + e, y = yhi + e^2, x = xlo - e): exact comparisons.
bool in_half(Vec2 p, int s, const Box& b) {
  switch (s) {
    case 0: return p.y >= b.ylo;
    case 1: return p.x <= b.xhi;
    case 2: return p.y <= b.yhi;
    default: return p.x >= b.xlo;
  }
}

bool inside(Vec2 p, const Box& b) { return in_half(p, 0, b) && in_half(p, 1, b) && in_half(p, 2, b) && in_half(p, 3, b); }

int isign(Sign s) { return static_cast<int>(s); }
int dsign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// Corner k of the shifted square is c_k + (sx e, sy e^2), k counter-clockwise
// from the lo corner. orient2d(a, b, corner) = orient2d(a, b, c_k)
//   + det(b - a, (sx e, sy e^2)) = O + dx sy e^2 - dy sx e.
// The first non-zero term decides; since b != a it is never zero.
constexpr std::array<int, 4> kSx{-1, 1, 1, -1};
constexpr std::array<int, 4> kSy{-1, -1, 1, 1};

Vec2 corner(const Box& b, int k) {
  switch (k) {
    case 0: return {b.xlo, b.ylo};
    case 1: return {b.xhi, b.ylo};
    case 2: return {b.xhi, b.yhi};
    default: return {b.xlo, b.yhi};
  }
}

int orient_corner(Vec2 a, Vec2 c, const Box& b, int k) {
  const int o = isign(orient2d(a, c, corner(b, k)));
  if (o != 0) return o;
  const int dy = dsign(c.y - a.y), dx = dsign(c.x - a.x);  // sign of a double difference is exact
  if (dy != 0) return -dy * kSx[k];
  return dx * kSy[k];
}

// Does the directed edge a -> c cross side s of the shifted square? Proper
// crossing: a and c strictly on opposite sides of the side line (never on it
// after the shift) and the side's two perturbed corners strictly on opposite
// sides of the edge line. Returns 0 (no), +1 (enters), -1 (leaves).
int side_crossing(Vec2 a, Vec2 c, const Box& b, int s) {
  const bool ha = in_half(a, s, b), hc = in_half(c, s, b);
  if (ha == hc) return 0;
  if (orient_corner(a, c, b, s) == orient_corner(a, c, b, (s + 1) % 4)) return 0;
  return ha ? -1 : 1;
}

mpq_class q(double v) { return mpq_class(v); }

// Coordinate along the line of the crossing of segment a-c with the line
// {y = c0} (horizontal) or {x = c0} (vertical); the segment must straddle it.
mpq_class crossing_coordinate(Vec2 a, Vec2 c, bool horizontal, double c0) {
  if (horizontal) return q(a.x) + (q(c0) - q(a.y)) * (q(c.x) - q(a.x)) / (q(c.y) - q(a.y));
  return q(a.y) + (q(c0) - q(a.x)) * (q(c.y) - q(a.y)) / (q(c.x) - q(a.x));
}

// Derivative of that coordinate with respect to c0.
mpq_class crossing_slope(Vec2 a, Vec2 c, bool horizontal) {
  if (horizontal) return (q(c.x) - q(a.x)) / (q(c.y) - q(a.y));
  return (q(c.y) - q(a.y)) / (q(c.x) - q(a.x));
}

int cmp_q(const mpq_class& u, const mpq_class& v) {
  const int r = cmp(u, v);
  return r > 0 ? 1 : (r < 0 ? -1 : 0);
}

// Sign of (crossing coordinate of segment a-c with the line at c0) - v, by
// one orient2d with the point of the line at coordinate v: for an upward
// edge, (v, c0) lies on its left iff v < x; for a rightward edge, (c0, v)
// lies on its left iff v > y.
int cmp_crossing_value(Vec2 a, Vec2 c, bool horizontal, double c0, double v) {
  if (horizontal) return isign(orient2d(a, c, {v, c0})) * dsign(c.y - a.y);
  return -isign(orient2d(a, c, {c0, v})) * dsign(c.x - a.x);
}

// Double approximation of the crossing coordinate and a bound on its error:
// x = a.x + (c0 - a.y) * (dx / dy) takes 6 rounded operations, so
// |x - fl(x)| <= 8 u (|a.x| + |t|) with t the product term (u = 2^-53,
// generous constant); the filter below doubles that margin again. The bound
// assumes no overflow or underflow: err is +inf (use the exact path) unless
// every input is below 2^500 in magnitude and the quotient and product are
// zero or above 2^-500.
double approx_crossing(Vec2 a, Vec2 c, bool horizontal, double c0, double& err) {
  const double big = 0x1p500, small = 0x1p-500;
  const double base = horizontal ? a.x : a.y;
  const double off = horizontal ? c0 - a.y : c0 - a.x;  // differences of doubles: no underflow error
  const double num = horizontal ? c.x - a.x : c.y - a.y;
  const double den = horizontal ? c.y - a.y : c.x - a.x;
  const double quot = num / den;
  const double t = off * quot;
  const bool ok = std::abs(a.x) < big && std::abs(a.y) < big && std::abs(c.x) < big && std::abs(c.y) < big &&
                  std::abs(c0) < big && (num == 0 || std::abs(quot) > small) && (t == 0 || std::abs(t) > small) &&
                  (off == 0 || quot == 0 || t != 0);
  err = ok ? 8.0 * 0x1p-53 * (std::abs(base) + std::abs(t)) : HUGE_VAL;
  return base + t;
}

// Compare the crossings of segments 1 and 2 with the line at c0 + sgn * eps
// (eps infinitesimal): the value at c0 first (a floating-point filter with a
// proven error bound, else GMP rationals), then the derivative (exact).
int cmp_on_line(Vec2 a1, Vec2 c1, Vec2 a2, Vec2 c2, bool horizontal, double c0, int sgn) {
  double e1 = 0, e2 = 0;
  const double x1 = approx_crossing(a1, c1, horizontal, c0, e1), x2 = approx_crossing(a2, c2, horizontal, c0, e2);
  const double margin = 2.0 * (e1 + e2) + 2.0 * 0x1p-53 * (std::abs(x1) + std::abs(x2));
  if (std::isfinite(margin) && std::abs(x1 - x2) > margin) return x1 > x2 ? 1 : -1;
  const int r = cmp_q(crossing_coordinate(a1, c1, horizontal, c0), crossing_coordinate(a2, c2, horizontal, c0));
  if (r != 0) return r;
  return sgn * cmp_q(crossing_slope(a1, c1, horizontal), crossing_slope(a2, c2, horizontal));
}

// Crossing of the directed edge with the side line, as a parameter along ∂C
// (a construction for reports; clamped into the side).
double crossing_t(Vec2 a, Vec2 c, const Box& b, int s) {
  const double len = b.xhi - b.xlo;
  const auto at_y = [&](double y) { return std::clamp(a.x + (y - a.y) * (c.x - a.x) / (c.y - a.y), b.xlo, b.xhi); };
  const auto at_x = [&](double x) { return std::clamp(a.y + (x - a.x) * (c.y - a.y) / (c.x - a.x), b.ylo, b.yhi); };
  switch (s) {
    case 0: return at_y(b.ylo) - b.xlo;
    case 1: return len + (at_x(b.xhi) - b.ylo);
    case 2: return 2 * len + (b.xhi - at_y(b.yhi));
    default: return 3 * len + (b.yhi - at_x(b.xlo));
  }
}

struct EdgeGeom {
  Vec2 a, c;
};

EdgeGeom geom(const Domain2& d, LoopEdge e) {
  const auto& loop = d.loops[static_cast<std::size_t>(e.loop)];
  const std::size_t n = loop.size();
  const std::size_t i = static_cast<std::size_t>(e.index);
  return {d.pslg.vertices[static_cast<std::size_t>(loop[i])], d.pslg.vertices[static_cast<std::size_t>(loop[(i + 1) % n])]};
}

int segment_id(const Domain2& d, LoopEdge e) {
  return d.loop_segments[static_cast<std::size_t>(e.loop)][static_cast<std::size_t>(e.index)];
}

bool less_edge(LoopEdge x, LoopEdge y) { return x.loop != y.loop ? x.loop < y.loop : x.index < y.index; }

struct EdgeCrossings {
  int count = 0;
  std::array<int, 2> side{};
  std::array<int, 2> dir{};  // +1 entry, -1 exit; entry first when both
};

EdgeCrossings crossings_of(Vec2 a, Vec2 c, const Box& b) {
  EdgeCrossings r;
  for (int s = 0; s < 4; ++s) {
    const int d = side_crossing(a, c, b, s);
    if (d == 0) continue;
    if (r.count == 2) throw InternalError("quad2d: a segment crosses a square more than twice");
    r.side[static_cast<std::size_t>(r.count)] = s;
    r.dir[static_cast<std::size_t>(r.count)] = d;
    ++r.count;
  }
  if (r.count == 2 && r.dir[0] < r.dir[1]) {
    std::swap(r.side[0], r.side[1]);
    std::swap(r.dir[0], r.dir[1]);
  }
  if (r.count == 2 && r.dir[0] == r.dir[1]) throw InternalError("quad2d: a segment enters a square twice");
  return r;
}

bool meets(Vec2 a, Vec2 c, const Box& b) {
  if (inside(a, b) || inside(c, b)) return true;
  for (int s = 0; s < 4; ++s)
    if (side_crossing(a, c, b, s) != 0) return true;
  return false;
}

// Crossing parity of the ray from the perturbed lo corner (xlo - e, ylo - e^2)
// in +x with every edge of P: is that corner inside P?
bool corner_in_domain(const Domain2& d, const Box& b) {
  bool in = false;
  for (std::size_t l = 0; l < d.loops.size(); ++l) {
    for (std::size_t k = 0; k < d.loops[l].size(); ++k) {
      const EdgeGeom g = geom(d, {static_cast<int>(l), static_cast<int>(k)});
      // y > ylo - e^2  <=>  y >= ylo
      const bool ua = g.a.y >= b.ylo, uc = g.c.y >= b.ylo;
      if (ua == uc) continue;
      const int dy = dsign(g.c.y - g.a.y);
      // The crossing is right of the point iff the point is left of the upward edge.
      if (orient_corner(g.a, g.c, b, 0) == dy) in = !in;
    }
  }
  return in;
}

// The first edge hit by the ray {(x, p.y + d) : x > p.x}, d infinitesimal
// (d << e^2), before it leaves the shifted square through the right side.
// Edges of loop skip_loop are ignored.
std::optional<std::size_t> first_hit(const Domain2& d, const Box& b, Vec2 p,
                                     const std::vector<std::pair<LoopEdge, int>>& edges, int skip_loop) {
  std::optional<std::size_t> best;
  EdgeGeom best_g{};
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (edges[i].first.loop == skip_loop) continue;
    const EdgeGeom g = geom(d, edges[i].first);
    if ((g.a.y > p.y) == (g.c.y > p.y)) continue;
    const int rp = cmp_crossing_value(g.a, g.c, true, p.y, p.x);
    if (rp < 0) continue;
    if (rp == 0 && dsign(g.c.x - g.a.x) * dsign(g.c.y - g.a.y) <= 0) continue;
    if (cmp_crossing_value(g.a, g.c, true, p.y, b.xhi) > 0) continue;  // x <= xhi  =>  x + O(d) < xhi + e
    if (!best || cmp_on_line(g.a, g.c, best_g.a, best_g.c, true, p.y, 1) < 0) {
      best = i;
      best_g = g;
    }
  }
  return best;
}

// The first crossing counter-clockwise after the point (xhi + e, p.y + d) on
// the right side (sorted crossings; wraps to 0).
std::size_t crossing_after_right_point(const Domain2& d, const Box& b, Vec2 p,
                                       const std::vector<detail::Crossing>& crossings) {
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const auto& c = crossings[i];
    if (c.side < 1) continue;
    if (c.side > 1) return i;
    const EdgeGeom g = geom(d, c.edge);
    // crossing height at x = xhi + e is y(xhi) + e * dy/dx
    const int r = cmp_crossing_value(g.a, g.c, false, b.xhi, p.y);
    if (r > 0) return i;
    if (r < 0) continue;
    if (dsign(g.c.y - g.a.y) * dsign(g.c.x - g.a.x) > 0) return i;
  }
  return 0;
}

struct Chain {
  std::size_t entry = 0, exit = 0;  // crossing indices
  std::vector<int> vertices;
  std::vector<LoopEdge> edges;
};

}  // namespace

std::vector<LoopEdge> edges_meeting(const Domain2& domain, const Square& square, std::span<const LoopEdge> candidates) {
  const Box b = box_of(square);
  std::vector<LoopEdge> out;
  for (const LoopEdge e : candidates) {
    const EdgeGeom g = geom(domain, e);
    if (meets(g.a, g.c, b)) out.push_back(e);
  }
  std::sort(out.begin(), out.end(), less_edge);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<LoopEdge> edges_meeting(const Domain2& domain, const Square& square) {
  std::vector<LoopEdge> all;
  for (std::size_t l = 0; l < domain.loops.size(); ++l)
    for (std::size_t k = 0; k < domain.loops[l].size(); ++k) all.push_back({static_cast<int>(l), static_cast<int>(k)});
  return edges_meeting(domain, square, all);
}

SquareComponents components(const Domain2& domain, const Square& square) {
  return components(domain, square, edges_meeting(domain, square));
}

SquareComponents components(const Domain2& domain, const Square& square, std::span<const LoopEdge> candidates,
                            const SquareComponents* container) {
  const Box b = box_of(square);
  const std::vector<LoopEdge> edges = edges_meeting(domain, square, candidates);
  SquareComponents result;
  result.square = square;

  // Loops: which cross ∂C, which lie inside C.
  const std::size_t nloops = domain.loops.size();
  std::vector<char> loop_crosses(nloops, 0), loop_touches(nloops, 0);
  std::vector<Chain> chains;
  std::vector<detail::Crossing>& crossings = result.crossings;
  for (const LoopEdge e : edges) {
    const EdgeGeom g = geom(domain, e);
    const EdgeCrossings ec = crossings_of(g.a, g.c, b);
    loop_touches[static_cast<std::size_t>(e.loop)] = 1;
    if (ec.count > 0) loop_crosses[static_cast<std::size_t>(e.loop)] = 1;
    if (ec.count == 0 || ec.dir[0] != 1) continue;
    // A chain starts here: walk forward along the loop to the exit.
    Chain ch;
    const int cid = static_cast<int>(chains.size());
    ch.entry = crossings.size();
    crossings.push_back({ec.side[0], true, e, cid, crossing_t(g.a, g.c, b, ec.side[0])});
    ch.edges.push_back(e);
    LoopEdge cur = e;
    EdgeCrossings cur_c = ec;
    const int n = static_cast<int>(domain.loops[static_cast<std::size_t>(e.loop)].size());
    for (int guard = 0; cur_c.count < 2; ++guard) {
      if (guard > n) throw InternalError("quad2d: a chain of the boundary inside a square does not end");
      ch.vertices.push_back(domain.loops[static_cast<std::size_t>(cur.loop)][static_cast<std::size_t>((cur.index + 1) % n)]);
      cur = {cur.loop, (cur.index + 1) % n};
      const EdgeGeom cg = geom(domain, cur);
      cur_c = crossings_of(cg.a, cg.c, b);
      ch.edges.push_back(cur);
      if (cur_c.count == 1) {
        if (cur_c.dir[0] != -1) throw InternalError("quad2d: chain inside a square re-enters without leaving");
        cur_c.side[1] = cur_c.side[0];
        cur_c.dir[1] = -1;
        break;
      }
      if (cur_c.count == 2) throw InternalError("quad2d: edge with an inside endpoint crosses the square twice");
    }
    const EdgeGeom lg = geom(domain, cur);
    ch.exit = crossings.size();
    crossings.push_back({cur_c.side[1], false, cur, cid, crossing_t(lg.a, lg.c, b, cur_c.side[1])});
    chains.push_back(std::move(ch));
  }

  // Sort crossings counter-clockwise along ∂C (exact).
  {
    std::vector<std::size_t> order(crossings.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      const auto& ci = crossings[i];
      const auto& cj = crossings[j];
      if (ci.side != cj.side) return ci.side < cj.side;
      const EdgeGeom gi = geom(domain, ci.edge), gj = geom(domain, cj.edge);
      switch (ci.side) {
        case 0: return cmp_on_line(gi.a, gi.c, gj.a, gj.c, true, b.ylo, -1) < 0;
        case 1: return cmp_on_line(gi.a, gi.c, gj.a, gj.c, false, b.xhi, 1) < 0;
        case 2: return cmp_on_line(gi.a, gi.c, gj.a, gj.c, true, b.yhi, 1) > 0;
        default: return cmp_on_line(gi.a, gi.c, gj.a, gj.c, false, b.xlo, -1) > 0;
      }
    });
    std::vector<std::size_t> where(crossings.size());
    std::vector<detail::Crossing> sorted;
    sorted.reserve(crossings.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      where[order[i]] = i;
      sorted.push_back(crossings[order[i]]);
    }
    crossings = std::move(sorted);
    for (Chain& ch : chains) {
      ch.entry = where[ch.entry];
      ch.exit = where[ch.exit];
    }
  }

  // Link chains into cycles: after an exit, the next crossing is an entry.
  const std::size_t nc = crossings.size();
  std::vector<int> next(chains.size(), -1);
  for (std::size_t c = 0; c < chains.size(); ++c) {
    const detail::Crossing& nx = crossings[(chains[c].exit + 1) % nc];
    if (!nx.entry) throw InternalError("quad2d: two consecutive exits along a square boundary");
    next[c] = nx.chain;
  }
  result.chain_component.assign(chains.size(), -1);
  for (std::size_t c = 0; c < chains.size(); ++c) {
    if (result.chain_component[c] >= 0) continue;
    const int comp = static_cast<int>(result.components.size());
    result.components.emplace_back();
    ComponentFaces& f = result.components.back();
    std::size_t k = c;
    while (result.chain_component[k] < 0) {
      result.chain_component[k] = comp;
      const Chain& ch = chains[k];
      f.vertices.insert(f.vertices.end(), ch.vertices.begin(), ch.vertices.end());
      for (const LoopEdge e : ch.edges) {
        f.edges.push_back(segment_id(domain, e));
        result.edge_component.push_back({e, comp});
      }
      const detail::Crossing& x = crossings[ch.exit];
      const detail::Crossing& en = crossings[(ch.exit + 1) % nc];
      // Crossings are sorted counter-clockwise from the lo corner, so the arc
      // passes through that corner iff the exit is the last crossing.
      f.boundary_arcs.push_back(
          {x.t, en.t, segment_id(domain, x.edge), segment_id(domain, en.edge), ch.exit + 1 == nc});
      k = static_cast<std::size_t>(next[k]);
    }
  }

  // Loops entirely inside C.
  std::vector<int> inside_loops;
  for (std::size_t l = 0; l < nloops; ++l)
    if (loop_touches[l] && !loop_crosses[l]) inside_loops.push_back(static_cast<int>(l));
  std::vector<int> loop_component(nloops, -1);
  if (chains.empty()) {
    const bool outer_inside = !inside_loops.empty() && inside_loops[0] == 0;
    bool in_domain = outer_inside;
    if (!in_domain) {
      const Vec2 centre{square.lo.x + 0.5 * square.side, square.lo.y + 0.5 * square.side};
      const Box cb = container ? box_of(container->square) : Box{};
      if (container && inside_loops.empty() && inside(centre, cb)) {
        // No P edge meets C, so the centre is not on ∂P.
        in_domain = locate_component(domain, *container, centre) >= 0;
      } else {
        in_domain = corner_in_domain(domain, b);
      }
    }
    if (in_domain) {
      result.components.emplace_back();
      result.components.back().whole_square = !outer_inside;
      if (!outer_inside) result.components.back().boundary_arcs.push_back({0.0, 4 * square.side, -1, -1, false});
      for (const int l : inside_loops) loop_component[static_cast<std::size_t>(l)] = 0;
    } else if (!inside_loops.empty()) {
      throw InternalError("quad2d: a hole lies inside a square that lies outside the domain");
    }
  } else {
    if (!inside_loops.empty() && inside_loops[0] == 0)
      throw InternalError("quad2d: the outer loop lies inside a square that boundary crosses");
    // Edges of inside loops take part in the ray shooting, tagged -2 - loop.
    std::vector<std::pair<LoopEdge, int>> ray_edges = result.edge_component;
    for (const int l : inside_loops)
      for (std::size_t k = 0; k < domain.loops[static_cast<std::size_t>(l)].size(); ++k)
        ray_edges.push_back({{l, static_cast<int>(k)}, -2 - l});
    // Resolve loops in decreasing order of their rightmost vertex, so that a
    // hit on another inside loop is already resolved (its rightmost vertex is
    // strictly further right than the hit point, which is right of ours).
    struct Item {
      Vec2 v;
      int loop;
    };
    std::vector<Item> items;
    for (const int l : inside_loops) {
      Vec2 best = domain.pslg.vertices[static_cast<std::size_t>(domain.loops[static_cast<std::size_t>(l)][0])];
      for (const int v : domain.loops[static_cast<std::size_t>(l)]) {
        const Vec2 p = domain.pslg.vertices[static_cast<std::size_t>(v)];
        if (p.x > best.x || (p.x == best.x && p.y > best.y)) best = p;
      }
      items.push_back({best, l});
    }
    std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) {
      if (x.v.x != y.v.x) return x.v.x > y.v.x;
      if (x.v.y != y.v.y) return x.v.y > y.v.y;
      return x.loop < y.loop;
    });
    for (const Item& it : items) {
      int comp = -1;
      const auto hit = first_hit(domain, b, it.v, ray_edges, it.loop);
      if (hit) {
        const int tag = ray_edges[*hit].second;
        comp = tag >= 0 ? tag : loop_component[static_cast<std::size_t>(-2 - tag)];
      } else {
        const detail::Crossing& c = crossings[crossing_after_right_point(domain, b, it.v, crossings)];
        if (c.entry) comp = result.chain_component[static_cast<std::size_t>(c.chain)];
      }
      if (comp < 0) throw InternalError("quad2d: cannot attach an inside loop to a component");
      loop_component[static_cast<std::size_t>(it.loop)] = comp;
    }
  }
  for (const int l : inside_loops) {
    const int comp = loop_component[static_cast<std::size_t>(l)];
    ComponentFaces& f = result.components[static_cast<std::size_t>(comp)];
    const auto& loop = domain.loops[static_cast<std::size_t>(l)];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      f.vertices.push_back(loop[k]);
      const LoopEdge e{l, static_cast<int>(k)};
      f.edges.push_back(segment_id(domain, e));
      result.edge_component.push_back({e, comp});
    }
  }
  for (ComponentFaces& f : result.components) {
    std::sort(f.vertices.begin(), f.vertices.end());
    f.vertices.erase(std::unique(f.vertices.begin(), f.vertices.end()), f.vertices.end());
    std::sort(f.edges.begin(), f.edges.end());
    f.edges.erase(std::unique(f.edges.begin(), f.edges.end()), f.edges.end());
    std::sort(f.boundary_arcs.begin(), f.boundary_arcs.end(),
              [](const BoundaryArc& x, const BoundaryArc& y) { return x.t0 < y.t0; });
  }
  std::sort(result.edge_component.begin(), result.edge_component.end(),
            [](const auto& x, const auto& y) { return less_edge(x.first, y.first); });
  return result;
}

int locate_component(const Domain2& domain, const SquareComponents& result, Vec2 p) {
  if (result.components.empty()) return -1;
  const Box b = box_of(result.square);
  const auto hit = first_hit(domain, b, p, result.edge_component, -1);
  if (hit) {
    // Just before the hit the ray is on the left of the edge iff it goes up.
    const EdgeGeom g = geom(domain, result.edge_component[*hit].first);
    return g.c.y > g.a.y ? result.edge_component[*hit].second : -1;
  }
  if (result.crossings.empty()) {
    // Whole square: p is in it. Otherwise the outer loop lies inside C and
    // the ray would have hit it if p were in P.
    return result.components[0].whole_square ? 0 : -1;
  }
  const detail::Crossing& c = result.crossings[crossing_after_right_point(domain, b, p, result.crossings)];
  if (!c.entry) return -1;
  return result.chain_component[static_cast<std::size_t>(c.chain)];
}

Square extended(const Square& square) {
  return {{square.lo.x - 2 * square.side, square.lo.y - 2 * square.side}, 5 * square.side};
}

int containing_component(const Domain2& domain, const SquareComponents& outer, const SquareComponents& inner_result,
                         const ComponentFaces& inner) {
  const auto find_in = [&](auto member, int id) {
    for (std::size_t c = 0; c < outer.components.size(); ++c) {
      const std::vector<int>& ids = outer.components[c].*member;
      if (std::binary_search(ids.begin(), ids.end(), id)) return static_cast<int>(c);
    }
    return -1;
  };
  if (!inner.vertices.empty()) return find_in(&ComponentFaces::vertices, inner.vertices.front());
  if (!inner.edges.empty()) return find_in(&ComponentFaces::edges, inner.edges.front());
  const Square& b = inner_result.square;
  return locate_component(domain, outer, {b.lo.x + 0.5 * b.side, b.lo.y + 0.5 * b.side});
}

}  // namespace pqmesh::quad2d
