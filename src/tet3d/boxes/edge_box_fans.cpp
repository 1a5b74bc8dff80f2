// Edge boxes with flat cones from the apex on E: F ∩ b and G ∩ b fanned
// from points of their own facets (thesis §4.5.3 with §4.5.4's fan; ours,
// docs/algorithm/tet3d_warp.md "Facet fans in flat edge boxes").
//
// Why: when the apex v on E lies within a few thousandths of h of a box
// face that carries a chord (a, b) of F, one of E's facets, every
// tetrahedron of the single-apex box with that chord contains the triangle
// (a, b, v) of F, a sliver because v is on F and nearly on the chord's line
// (bounded seed 172, aspect × alpha 17,198). The two-point construction
// (edge_box.cpp) cannot help: it keeps every triangle of F ∩ b on v. Here
// the polygon of the guilty facet gets a fan point of its own:
//   (A) apex u on one facet F (a central point of F ∩ b), coned to every
//       face triangle, and G ∩ b fanned from v (its chords coned to u);
//   (B) an interior grid point w coned to every face triangle, and F ∩ b
//       and G ∩ b each fanned from v or from a central point of its own,
//       coned to w.
// E ∩ b stays the two mesh edges from v to its ends in both: they are
// sides of the fan polygons (edge_polygon). The tetrahedra are the cones of
// a closed outward surface (the face triangles and the fans of F ∩ b and
// G ∩ b, each polygon's fan being the same 2-chain from any point), so
// with every one positive by exact orient3d they tile P ∧ I(b) face to
// face; a candidate with one that is not positive is rejected. That needs
// a convex E (for a reflex one u on F sees G ∩ b from outside, so (A)
// is rejected, and (B)'s w must be in the kernel: it is tried all the same).
#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "tet3d/boxes/box_assembler.hpp"
#include "tet3d/boxes/tet_shape.hpp"

namespace pqmesh::tet3d {

// F ∩ b of an edge box as a closed polygon: its chords (face-triangle
// edges on F, E's crossings included) form one chain from one end of
// E ∩ b to the other; E's two pieces through v close it, continuing the
// chain's direction (end -> v -> start), so that chords and pieces turn
// one way around the polygon and fan() orients them alike. Empty when the
// chords are not one simple chain (then this facet gets no fan point).
BoxAssembler::Chords BoxAssembler::edge_polygon(const Chords& chord, int v) const {
  std::map<int, int> next, prev;
  for (const auto& [edge, directed] : chord) {
    if (!next.emplace(directed.first, directed.second).second) return {};
    if (!prev.emplace(directed.second, directed.first).second) return {};
  }
  int start = -1, starts = 0;
  for (const auto& [p, q] : next)
    if (!prev.contains(p)) {
      start = p;
      ++starts;
    }
  if (starts != 1) return {};
  // Walk the chain: it must use every chord (no separate cycle).
  int end = start;
  std::size_t walked = 0;
  for (auto it = next.find(end); it != next.end(); it = next.find(end)) {
    end = it->second;
    ++walked;
  }
  if (walked != chord.size() || end == v || start == v) return {};
  Chords closed = chord;
  closed.emplace(std::pair{std::min(end, v), std::max(end, v)}, std::pair{end, v});
  closed.emplace(std::pair{std::min(v, start), std::max(v, start)}, std::pair{v, start});
  return closed;
}

// The best of (A), on either facet, and (B), over their candidates: the
// central points of each closed polygon (central_points) for u, the
// interior grid points at i/8, j/8, k/8 of the box (interior_grid_points)
// for w, each fan of (B) chosen for its own polygon (v first, then the
// central points, strictly better only). (B) needs both polygons closed.
// Ties go to the first found: (A) on f(), (A) on g(), then (B).
BoxAssembler::FacetFans BoxAssembler::best_facet_fans(std::int32_t leaf, int edge, const std::vector<Tri>& tris,
                                                      int v) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const EdgeCone& ec = squares_.cone(edge);
  FacetFans best;
  if (ec.flat()) return best;  // F and G are one plane: no tetrahedron of (A) or (B) has volume
  const FacetPlane* pl[2] = {&ec.f(), &ec.g()};
  const Chords chord[2] = {chords(leaf, tris, *pl[0], edge), chords(leaf, tris, *pl[1], edge)};
  const Chords closed[2] = {edge_polygon(chord[0], v), edge_polygon(chord[1], v)};
  std::vector<Vec3> points[2];
  for (int i = 0; i < 2; ++i)
    if (!closed[i].empty()) points[i] = central_points(closed[i], *pl[i]);
  const Vec3 V = book_.point(v);
  // (A): u on facet i, the other facet's chords fanned from v.
  for (int i = 0; i < 2; ++i)
    for (const Vec3& u : points[i]) {
      double s = worst_cone(tris, u);
      if (s < best.shape) s = std::max(s, worst_fan(chord[1 - i], V, u, true));
      if (s < best.shape) {
        best = {s, false, i, {}, {}, {}};
        best.on[i] = u;
      }
    }
  // (B): w inside, each polygon fanned from v or its best central point.
  if (points[0].empty() || points[1].empty()) return best;
  for (const GridPoint& g : interior_grid_points(tree_.key(leaf), 8)) {
    const Vec3 W = grid_coordinates(tree_, g);
    double s = worst_cone(tris, W);
    FacetFans c{kInf, true, 0, {}, {true, true}, g};
    for (int f = 0; f < 2 && s < best.shape; ++f) {
      double fan_best = worst_fan(chord[f], V, W, true);
      for (const Vec3& u : points[f]) {
        const double t = worst_fan(closed[f], u, W, true);
        if (t < fan_best) {
          fan_best = t;
          c.on[f] = u;
          c.from_v[f] = false;
        }
      }
      s = std::max(s, fan_best);
    }
    if (s < best.shape) {
      c.shape = s;
      best = c;
    }
  }
  return best;
}

// The tetrahedra of construction c (see best_facet_fans). The fan points
// are keyed by the box centre and their facet (EdgeFacetPoint); w, an
// interior grid point of the leaf, is in no other box and never warped.
void BoxAssembler::make_facet_fans(std::int32_t leaf, int edge, const std::vector<Tri>& tris, int v,
                                   const FacetFans& c) {
  const EdgeCone& ec = squares_.cone(edge);
  const FacetPlane* pl[2] = {&ec.f(), &ec.g()};
  const GridPoint centre = key_centre(tree_.key(leaf));
  auto fan_point = [&](int f) {
    return book_.id({VertexKind::EdgeFacetPoint, centre, {}, pl[f]->facet()}, [&] { return c.on[f]; });
  };
  if (!c.centred) {
    const int u = fan_point(c.apex_facet);
    for (const Tri& t : tris) cone(leaf, t, u);
    for (const auto& [e, directed] : chords(leaf, tris, *pl[1 - c.apex_facet], edge))
      tet(leaf, "fan", directed.first, directed.second, v, u);
    return;
  }
  const int w = centre_vertex(c.w);
  for (const Tri& t : tris) cone(leaf, t, w);
  for (int f = 0; f < 2; ++f) {
    const Chords chord = chords(leaf, tris, *pl[f], edge);
    const int u = c.from_v[f] ? v : fan_point(f);
    for (const auto& [e, directed] : c.from_v[f] ? chord : edge_polygon(chord, v))
      tet(leaf, "fan", directed.first, directed.second, u, w);
  }
}

}  // namespace pqmesh::tet3d
