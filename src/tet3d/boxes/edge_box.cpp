// Edge boxes (thesis §4.5.3): the apex on E and the two-cone-point constructions.
#include <algorithm>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "pqmesh/errors.hpp"
#include "tet3d/boxes/box_assembler.hpp"
#include "tet3d/points/edge_point.hpp"
#include "tet3d/boxes/tet_shape.hpp"

namespace pqmesh::tet3d {

void BoxAssembler::edge_box(std::int32_t leaf, int edge) {
  const BoxKey<3>& key = tree_.key(leaf);
  std::vector<Tri> tris;
  box_tris(key, squares_.faces_of(BoxKind::Edge, edge), tris);
  const DomainEdge& e = domain_.edges.at(static_cast<std::size_t>(edge));
  const Vec3 a = domain_.plc.vertices[static_cast<std::size_t>(e.a)];
  const Vec3 b = domain_.plc.vertices[static_cast<std::size_t>(e.b)];
  const Vec3 lo = grid_coordinates(tree_, key_corner(key, 0)), hi = grid_coordinates(tree_, key_corner(key, 7));
  const auto [t0, t1] = clip_segment(a, b, lo, hi);
  if (!(t0 < t1))
    throw InternalError("tet3d: edge " + std::to_string(edge) + " misses edge box " + std::to_string(leaf));
  // §4.5.3: the midpoint of E ∩ I(b), I(b) the warped box: E enters and
  // leaves it at its two Case B vertices on b's faces (E is convex-clipped
  // by the cube; no P vertex in an edge box), wherever they were put
  // (warped_crossing.hpp); the midpoint of the clip when they are not two.
  std::vector<int> ends;
  for (const Tri& t : tris)
    for (const int id : t)
      if (book_.key(id).kind == VertexKind::EdgeCrossing && book_.key(id).facet == edge &&
          std::find(ends.begin(), ends.end(), id) == ends.end())
        ends.push_back(id);
  const double tm = 0.5 * (t0 + t1);
  const Vec3 mid = ends.size() == 2 ? 0.5 * (book_.point(ends[0]) + book_.point(ends[1])) : a + tm * (b - a);
  const VertexKey vk{VertexKind::EdgeMidpoint, key_centre(key), {}, edge};
  const int v = book_.id(vk, [&] { return apex_on_edge(tris, a, b, ends, mid, t0, t1); });
  ++out_.stats.edge;
  // A non-positive cone (a warp pushed a face past E): two cone points or,
  // failing that, the rebuild loop; flat cones: another construction only
  // when strictly better (two_apex_box, flat_edge_box).
  const double single = worst_cone(tris, book_.point(v));
  const bool positive = single < std::numeric_limits<double>::infinity();
  if (!positive && two_apex_box(leaf, tris, v)) {
    ++out_.stats.edge_two_apex;
    return;
  }
  if (positive && single > kFlatCone && flat_edge_box(leaf, edge, tris, v, single)) return;
  for (const Tri& t : tris) cone(leaf, t, v);
}

// An edge box whose apex v on E sees every face triangle, but some of its cones
// are flat (worst tet_shape `single` above kFlatCone): the best of two
// constructions of ours (docs/algorithm/tet3d_warp.md "Flat cones from two
// points", "Facet fans in flat edge boxes"), taken only if its worst tet_shape
// is strictly better than `single`, the two-point construction on ties. Both
// make only tetrahedra that are positive by exact orient3d, so the rebuild loop
// never reacts to them; floats only choose between valid constructions.
bool BoxAssembler::flat_edge_box(std::int32_t leaf, int edge, const std::vector<Tri>& tris, int v, double single) {
  const TwoApex two = flat_two_apex(leaf, tris, v);
  const FacetFans fans = facet_fans_ ? best_facet_fans(leaf, edge, tris, v) : FacetFans{};
  if (fans.shape < two.shape && fans.shape < single) {
    make_facet_fans(leaf, edge, tris, v, fans);
    ++out_.stats.edge_facet_fans;
    return true;
  }
  if (!(two.shape < single)) return false;
  make_two_apex(leaf, tris, v, two);
  ++out_.stats.edge_two_apex_flat;
  return true;
}

// An edge box whose apex v on E does not see every face triangle (exact
// orient3d; our construction, docs/algorithm/tet3d_warp.md "Two cone points"):
// a warp pushed part of a face into the box past every point of E (suite
// seed 67: a face shared with smaller edge boxes of the same E, which E
// crosses just above their boundary; §4.3's first pass moves its lower
// half h_small/8 away from E, while E stays within 0.011 h of it).
// A set S' of face triangles (the "far" set) is coned from a second point
// w inside the box, the rest from v, and the gap between the two stars is
// filled by cone(v, (a, b, w)) for every edge a -> b of the rim of S' (an
// edge of a triangle of S' whose reverse is in none). As chains
// cone(v, S') = cone(w, S') + Σ cone(v, (a, b, w)) (the triangles (a, b, w)
// have the rim of S' as boundary), so the tetrahedra have the boundary of
// the single-apex star, and with every one positive (exact orient3d) they
// tile P ∧ I(b) face to face. E ∩ b stays the two mesh edges from v to its
// ends (each end is on a chord, so a cone or rim tetrahedron of v has it).
// S' starts as the triangles v does not see; a rim edge whose tetrahedron
// is not positive (v cannot see it past the pushed part) adds the triangle
// across it, until every rim tetrahedron is positive (then a valid w) or a
// triangle w does not see, or a rim edge on F or G, stops it (w rejected).
// w: the interior grid points at i/4, j/4, k/4 of the box (i, j, k in
// 1..3, in that order); the one with the best worst tet_shape among the
// valid ones, the first on ties (floats only choose between valid
// constructions). Returns false (nothing made; the rebuild loop then
// freezes the warp, as before) when none is valid or the construction is
// off for this pass (allow_two_apex; two_apex_points() records the box
// vertices of a box that had a valid one, mesh_boxes).
bool BoxAssembler::two_apex_box(std::int32_t leaf, const std::vector<Tri>& tris, int v) {
  std::vector<char> far0(tris.size(), 0);
  for (std::size_t n = 0; n < tris.size(); ++n) far0[n] = seen(tris[n], book_.point(v)) ? 0 : 1;
  const TwoApex best = best_two_apex(leaf, tris, v, far0);
  if (!(best.shape < std::numeric_limits<double>::infinity())) return false;
  for (const Tri& t : tris)
    for (const int id : t)
      if (book_.key(id).kind == VertexKind::Grid || book_.key(id).kind == VertexKind::Warped)
        two_apex_points_.push_back(book_.key(id).p);
  if (!two_apex_) return false;
  make_two_apex(leaf, tris, v, best);
  return true;
}

// Flat cones from v, first construction (docs/algorithm/tet3d_warp.md "Flat
// cones from two points"): E runs within a few thousandths of h of a box face
// (or a face warped towards it), so v, on E, lies almost in that face's plane
// (bounded seed 167: apex 0.00015 h from the face triangle through E's own
// crossing; seed 172: 0.00026 h from a face frozen on the grid). The same
// two-point construction as two_apex_box, with the far set S' seeded by the k
// face triangles with the worst cones from v (k = 1 .. all, ties in triangle
// order) and grown until every rim tetrahedron is positive; among every seed
// and every w, the best worst tet_shape over the box (the first on ties;
// +infinity when none is valid). Not recorded in two_apex_points() (that list
// decides mesh_boxes' second run).
BoxAssembler::TwoApex BoxAssembler::flat_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v) {
  const Vec3 V = book_.point(v);
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t n = 0; n < tris.size(); ++n)
    order.push_back({tet_shape(book_.point(tris[n][0]), book_.point(tris[n][2]), book_.point(tris[n][1]), V), n});
  std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  TwoApex best;
  std::vector<char> far0(tris.size(), 0);
  for (const auto& [shape, n] : order) {
    far0[n] = 1;
    TwoApex c = best_two_apex(leaf, tris, v, far0);
    if (c.shape < best.shape) best = std::move(c);
  }
  return best;
}

BoxAssembler::TwoApex BoxAssembler::best_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v,
                                                  const std::vector<char>& far0) {
  const BoxKey<3>& key = tree_.key(leaf);
  TwoApex best;
  const std::vector<GridPoint> candidates = interior_grid_points(key, 4);
  if (candidates.empty()) return best;
  const Vec3 V = book_.point(v);
  // Directed edge -> its face triangle (each directed edge is in one).
  std::map<std::pair<int, int>, std::size_t> owner;
  for (std::size_t n = 0; n < tris.size(); ++n)
    for (std::size_t k = 0; k < 3; ++k) owner.emplace(std::pair{tris[n][k], tris[n][(k + 1) % 3]}, n);
  // The far set grown for w (empty when w is rejected).
  auto grow = [&](Vec3 W) {
    std::vector<char> far = far0;
    for (std::size_t n = 0; n < tris.size(); ++n)
      if (far[n] && !seen(tris[n], W)) return std::vector<char>{};
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t n = 0; n < tris.size(); ++n) {
        if (!far[n]) continue;
        for (std::size_t k = 0; k < 3; ++k) {
          const int x = tris[n][k], y = tris[n][(k + 1) % 3];
          const auto across = owner.find({y, x});
          if (across != owner.end() && far[across->second]) continue;
          if (orient3d(book_.point(x), W, book_.point(y), V) == Sign::Positive) continue;
          if (across == owner.end() || !seen(tris[across->second], W)) return std::vector<char>{};
          far[across->second] = 1;
          changed = true;
        }
      }
    }
    return far;
  };
  for (const GridPoint& g : candidates) {
    const Vec3 W = grid_coordinates(tree_, g);
    std::vector<char> far = grow(W);
    if (far.empty()) continue;
    double s = 0;
    for (std::size_t n = 0; n < tris.size(); ++n) {
      const Vec3 x = book_.point(tris[n][0]), y = book_.point(tris[n][2]), z = book_.point(tris[n][1]);
      s = std::max(s, tet_shape(x, y, z, far[n] ? W : V));
    }
    for (const auto& [x, y] : rim_of(tris, owner, far))
      s = std::max(s, tet_shape(book_.point(x), W, book_.point(y), V));
    if (s < best.shape) best = {s, g, std::move(far)};
  }
  return best;
}

// The rim of far set `far`: edges a -> b of its triangles whose reverse is
// in no triangle of the set.
std::vector<std::pair<int, int>> BoxAssembler::rim_of(const std::vector<Tri>& tris,
                                                      const std::map<std::pair<int, int>, std::size_t>& owner,
                                                      const std::vector<char>& far) {
  std::vector<std::pair<int, int>> rim;
  for (std::size_t n = 0; n < tris.size(); ++n)
    if (far[n])
      for (std::size_t k = 0; k < 3; ++k) {
        const int x = tris[n][k], y = tris[n][(k + 1) % 3];
        const auto across = owner.find({y, x});
        if (across == owner.end() || !far[across->second]) rim.push_back({x, y});
      }
  return rim;
}

// The tetrahedra of a two-point construction: cones from w over S', from v
// over the rest, (a, w, b, v) over the rim. w is an interior grid point of
// the leaf: no other box has it, never warped.
void BoxAssembler::make_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v, const TwoApex& c) {
  const int w = centre_vertex(c.w);
  std::map<std::pair<int, int>, std::size_t> owner;
  for (std::size_t n = 0; n < tris.size(); ++n)
    for (std::size_t k = 0; k < 3; ++k) owner.emplace(std::pair{tris[n][k], tris[n][(k + 1) % 3]}, n);
  for (std::size_t n = 0; n < tris.size(); ++n) cone(leaf, tris[n], c.far[n] ? w : v);
  for (const auto& [x, y] : rim_of(tris, owner, c.far)) tet(leaf, "rim", x, w, y, v);
}

// The apex on E (our choice within §4.5.3): the midpoint of E ∩ I(b),
// unless a point at 1/4, 3/8, 5/8 or 3/4 of it makes the worst cone
// better (tet_shape): a chord of F or G on a box face whose line meets E
// near the midpoint makes the boundary triangle (chord, midpoint) nearly
// degenerate. Every candidate is rounded onto E (edge_point.hpp) and taken
// only if all its cones are positive (exact orient3d) and so are the
// midpoint's.
Vec3 BoxAssembler::apex_on_edge(const std::vector<Tri>& tris, Vec3 a, Vec3 b, const std::vector<int>& ends, Vec3 mid,
                                double t0, double t1) {
  const Vec3 p0 = ends.size() == 2 ? book_.point(ends[0]) : a + t0 * (b - a);
  const Vec3 p1 = ends.size() == 2 ? book_.point(ends[1]) : a + t1 * (b - a);
  auto worst = [&](Vec3 apex) { return worst_cone(tris, apex); };
  Vec3 best = round_onto_segment(a, b, mid);
  double best_shape = worst(best);
  // A midpoint with a non-positive cone is kept: the warp that caused it
  // is found and frozen by the rebuild loop (mesh_boxes).
  if (best_shape == std::numeric_limits<double>::infinity()) return best;
  bool moved = false;
  for (const double t : {0.25, 0.375, 0.625, 0.75}) {
    const Vec3 c = round_onto_segment(a, b, p0 + t * (p1 - p0));
    const double s = worst(c);
    if (s < best_shape) {
      best = c;
      best_shape = s;
      moved = true;
    }
  }
  out_.stats.edge_apex_moved += moved ? 1 : 0;
  return best;
}

}  // namespace pqmesh::tet3d
