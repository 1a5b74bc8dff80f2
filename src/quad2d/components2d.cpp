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
#include <vector>

#include "pqmesh/errors.hpp"
#include "quad2d/shifted_square.hpp"

namespace pqmesh::quad2d {

using namespace detail;  // the shifted-square geometry (shifted_square.hpp)

namespace {

struct Chain {
  std::size_t entry = 0, exit = 0;  // crossing indices
  std::vector<int> vertices;
  std::vector<LoopEdge> edges;
};


// Loops meeting C: touches (an edge meets C_e) and crosses (an edge crosses ∂C_e).
struct LoopFlags {
  std::vector<char> crosses, touches;
};

// Step 2: the chain starting at edge e (endpoints g), which enters C_e (ec:
// its crossings): walks forward along the loop to the exit, appending the entry
// and exit crossings (chain id cid) to `crossings`.
Chain trace_chain(const Domain2& domain, const Box& b, LoopEdge e, const EdgeGeom& g, const EdgeCrossings& ec, int cid,
                  std::vector<detail::Crossing>& crossings) {
  Chain ch;
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
  return ch;
}

// Steps 1-2: the chains, one per edge entering C_e, in edge order, with
// their crossings (unsorted); flags which loops cross ∂C and which meet C.
std::vector<Chain> trace_chains(const Domain2& domain, const Box& b, const std::vector<LoopEdge>& edges,
                                std::vector<detail::Crossing>& crossings, LoopFlags& loops) {
  std::vector<Chain> chains;
  for (const LoopEdge e : edges) {
    const EdgeGeom g = geom(domain, e);
    const EdgeCrossings ec = crossings_of(g.a, g.c, b);
    loops.touches[static_cast<std::size_t>(e.loop)] = 1;
    if (ec.count > 0) loops.crosses[static_cast<std::size_t>(e.loop)] = 1;
    if (ec.count == 0 || ec.dir[0] != 1) continue;
    // A chain starts here: walk forward along the loop to the exit.
    chains.push_back(trace_chain(domain, b, e, g, ec, static_cast<int>(chains.size()), crossings));
  }
  return chains;
}

// Step 3: sort crossings counter-clockwise along ∂C (exact), renumbering the
// chains' entry and exit indices.
void sort_crossings(const Domain2& domain, const Box& b, std::vector<detail::Crossing>& crossings,
                    std::vector<Chain>& chains) {
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

// Step 3: link chains into cycles (after an exit, the next crossing is an
// entry), one component per cycle with its chains' faces and boundary arcs.
void link_cycles(const Domain2& domain, const std::vector<Chain>& chains, SquareComponents& result) {
  const std::vector<detail::Crossing>& crossings = result.crossings;
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
}

// Step 4 when ∂P does not cross ∂C: C lies in P (one component, the whole
// square unless the outer loop lies inside C) or outside it (no component);
// every inside loop goes to component 0.
void components_without_chains(const Domain2& domain, const Square& square, const Box& b,
                               const SquareComponents* container, const std::vector<int>& inside_loops,
                               SquareComponents& result, std::vector<int>& loop_component) {
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
}

// An inside loop with its rightmost vertex (largest x, then y).
struct Item {
  Vec2 v;
  int loop;
};

// The inside loops in decreasing order of their rightmost vertex, so that a
// hit on another inside loop is already resolved (its rightmost vertex is
// strictly further right than the hit point, which is right of ours).
std::vector<Item> loops_right_to_left(const Domain2& domain, const std::vector<int>& inside_loops) {
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
  return items;
}

// Step 4 when chains exist: each inside loop joins the component its tether
// ray from the rightmost vertex reaches (loop_component).
void attach_inside_loops(const Domain2& domain, const Box& b, const std::vector<int>& inside_loops,
                         const SquareComponents& result, std::vector<int>& loop_component) {
  if (!inside_loops.empty() && inside_loops[0] == 0)
    throw InternalError("quad2d: the outer loop lies inside a square that boundary crosses");
  // Edges of inside loops take part in the ray shooting, tagged -2 - loop.
  std::vector<std::pair<LoopEdge, int>> ray_edges = result.edge_component;
  for (const int l : inside_loops)
    for (std::size_t k = 0; k < domain.loops[static_cast<std::size_t>(l)].size(); ++k)
      ray_edges.push_back({{l, static_cast<int>(k)}, -2 - l});
  for (const Item& it : loops_right_to_left(domain, inside_loops)) {
    int comp = -1;
    const auto hit = first_hit(domain, b, it.v, ray_edges, it.loop);
    if (hit) {
      const int tag = ray_edges[*hit].second;
      comp = tag >= 0 ? tag : loop_component[static_cast<std::size_t>(-2 - tag)];
    } else {
      const detail::Crossing& c = result.crossings[crossing_after_right_point(domain, b, it.v, result.crossings)];
      if (c.entry) comp = result.chain_component[static_cast<std::size_t>(c.chain)];
    }
    if (comp < 0) throw InternalError("quad2d: cannot attach an inside loop to a component");
    loop_component[static_cast<std::size_t>(it.loop)] = comp;
  }
}

// Adds every inside loop's vertices and edges to its component.
void add_inside_loop_faces(const Domain2& domain, const std::vector<int>& inside_loops,
                           const std::vector<int>& loop_component, SquareComponents& result) {
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
}

// Face lists sorted and unique, arcs by t0, edge_component by edge.
void sort_faces(SquareComponents& result) {
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
}
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
  LoopFlags loops{std::vector<char>(nloops, 0), std::vector<char>(nloops, 0)};
  std::vector<Chain> chains = trace_chains(domain, b, edges, result.crossings, loops);
  sort_crossings(domain, b, result.crossings, chains);
  link_cycles(domain, chains, result);

  // Loops entirely inside C.
  std::vector<int> inside_loops;
  for (std::size_t l = 0; l < nloops; ++l)
    if (loops.touches[l] && !loops.crosses[l]) inside_loops.push_back(static_cast<int>(l));
  std::vector<int> loop_component(nloops, -1);
  if (chains.empty()) components_without_chains(domain, square, b, container, inside_loops, result, loop_component);
  else attach_inside_loops(domain, b, inside_loops, result, loop_component);
  add_inside_loop_faces(domain, inside_loops, loop_component, result);
  sort_faces(result);
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
