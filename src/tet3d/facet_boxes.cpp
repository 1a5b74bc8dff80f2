#include "tet3d/facet_boxes.hpp"

#include <algorithm>
#include <utility>
#include <array>
#include <initializer_list>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "pqmesh/errors.hpp"
#include "tet3d/cut_square.hpp"
#include "tet3d/edge_point.hpp"
#include "tet3d/facet_plane.hpp"
#include "tet3d/tet_shape.hpp"
#include "tet3d/point_book.hpp"
#include "tet3d/warp.hpp"
#include "tet3d/warp_candidates.hpp"

namespace pqmesh::tet3d {

GridPoint united_lo(const BoxKey<3>& key, std::uint8_t block) {
  GridPoint lo = key_corner(key, 0);
  for (int a = 0; a < 3; ++a)
    if ((block >> a) & 1) lo.f[static_cast<std::size_t>(a)] -= key.fine_side();
  return lo;
}

void united_face_squares(const BoxKey<3>& key, std::uint8_t block, int axis, bool upper, const CornerSet& corners,
                         std::vector<FaceSquare>& out) {
  const std::int64_t fs = key.fine_side();
  for (int k = 0; k < 4; ++k) {
    FaceSquare s;
    s.n = axis;
    s.u = (axis + 1) % 3;
    s.v = (axis + 2) % 3;
    s.upper = upper;
    s.lo = united_lo(key, block);
    if (upper) s.lo.f[static_cast<std::size_t>(axis)] += 2 * fs;
    s.lo.f[static_cast<std::size_t>(s.u)] += (k & 1) ? fs : 0;
    s.lo.f[static_cast<std::size_t>(s.v)] += (k & 2) ? fs : 0;
    s.side = fs;
    split_square(s, corners, out);
  }
}

void job_squares(const OctTree& tree, const CornerSet& corners, const BoxJob& job, std::vector<FaceSquare>& out) {
  for (int axis = 0; axis < 3; ++axis)
    for (const bool upper : {false, true}) {
      if (job.kind == BoxKind::Vertex)
        united_face_squares(tree.key(job.leaf), job.block, axis, upper, corners, out);
      else
        face_squares(tree.key(job.leaf), axis, upper, corners, out);
    }
}

BoxFaces job_faces(const SquareDispatcher& squares, const BoxJob& job) {
  if (job.kind == BoxKind::FromFacet)
    return squares.faces_of(job.facet < 0 ? BoxKind::Empty : BoxKind::Facet, job.facet);
  return squares.faces_of(job.kind, job.apex);
}

namespace {

using Tri = std::array<int, 3>;

int dominant_axis(Vec3 n) {
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  return ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
}

class Assembler {
 public:
  Assembler(const OctTree& tree, const CornerSet& corners, const Domain3& domain, const WarpTable* warps)
      : tree_(tree), corners_(corners), domain_(domain), warps_(warps) {
    book_.set_warps(warps);
  }

  void empty_box(std::int32_t leaf) {
    const BoxKey<3>& key = tree_.key(leaf);
    std::vector<GridTriangle> tris;
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) triangulate_box_face(key, axis, upper, corners_, tris);
    const int c = centre_vertex(key_centre(key));
    for (const GridTriangle& t : tris) cone(leaf, {grid(t[0]), grid(t[1]), grid(t[2])}, c);
    ++out_.stats.empty;
  }

  void facet_box(std::int32_t leaf, int facet) {
    const FacetPlane& plane = squares_.plane(facet);
    const BoxKey<3>& key = tree_.key(leaf);
    // Face triangles of P ∧ b, right-hand normal out of the box.
    std::vector<Tri> tris;
    box_tris(key, squares_.faces_of(BoxKind::Facet, facet), tris);
    // Edges of face triangles on F: the boundary of the polygon F ∩ b, keyed
    // by (smaller id, larger id), each kept with the direction a -> b it has
    // in its face triangle. Every such edge lies on the face triangles' side
    // of one box face, so it is in exactly one of them (the part of a face
    // beyond F yields no triangles).
    const auto chord = chords(leaf, tris, plane);
    const GridPoint centre = key_centre(key);
    const Vec3 C = grid_coordinates(tree_, centre);
    const double h = tree_.side(leaf);
    const double d = plane.distance(C);
    if (d <= -h / 4) {
      const int v = centre_vertex(centre);
      double cone_worst = 0;
      for (const Tri& t : tris) {
        cone(leaf, t, v);
        cone_worst = std::max(cone_worst, tet_shape(book_.point(t[0]), book_.point(t[2]), book_.point(t[1]),
                                                    book_.point(v)));
      }
      fan(leaf, chord, plane, VertexKind::FacetCentre, centre, v, cone_worst);
      ++out_.stats.inside;
    } else if (d < h / 4) {
      const VertexKey vk{VertexKind::BoxOnFacet, centre, {}, facet};
      const int v = book_.id(vk, [&] { return plane.settle(C - d * plane.normal(), dominant_axis(plane.normal())); });
      for (const Tri& t : tris) cone(leaf, t, v);
      ++out_.stats.on_facet;
    } else {
      for (const Tri& t : tris) prism(leaf, t, centre, C, plane);
      ++out_.stats.beyond;
    }
  }

  void edge_box(std::int32_t leaf, int edge) {
    const BoxKey<3>& key = tree_.key(leaf);
    std::vector<Tri> tris;
    box_tris(key, squares_.faces_of(BoxKind::Edge, edge), tris);
    const DomainEdge& e = domain_.edges.at(static_cast<std::size_t>(edge));
    const Vec3 a = domain_.plc.vertices[static_cast<std::size_t>(e.a)];
    const Vec3 b = domain_.plc.vertices[static_cast<std::size_t>(e.b)];
    const Vec3 lo = grid_coordinates(tree_, key_corner(key, 0)), hi = grid_coordinates(tree_, key_corner(key, 7));
    const auto [t0, t1] = clip_segment(a, b, lo, hi);
    if (!(t0 < t1)) throw InternalError("tet3d: edge " + std::to_string(edge) + " misses edge box " + std::to_string(leaf));
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
    // failing that, the rebuild loop; flat cones: two cone points only when
    // strictly better (two_apex_box, flat_two_apex_box).
    const double single = worst_cone(tris, book_.point(v));
    const bool positive = single < std::numeric_limits<double>::infinity();
    if (!positive && two_apex_box(leaf, tris, v)) {
      ++out_.stats.edge_two_apex;
      return;
    }
    if (positive && single > kFlatCone && flat_two_apex_box(leaf, tris, v, single)) {
      ++out_.stats.edge_two_apex_flat;
      return;
    }
    for (const Tri& t : tris) cone(leaf, t, v);
  }

  // An edge box whose apex v on E does not see every face triangle (exact
  // orient3d; our construction, docs/ALGORITHM.md §12.5 "two cone points"):
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
  bool two_apex_box(std::int32_t leaf, const std::vector<Tri>& tris, int v) {
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

  // An edge box whose apex v on E sees every face triangle, but some of its
  // cones are flat (worst tet_shape `single` above kFlatCone; our
  // construction, docs/ALGORITHM.md §12.5 "flat cones from two points"): E
  // runs within a few thousandths of h of a box face (or a face warped
  // towards it), so v, on E, lies almost in that face's plane (bounded seed
  // 167: apex 0.00015 h from the face triangle through E's own crossing;
  // seed 172: 0.00026 h from a face frozen on the grid). The same two-point
  // construction as two_apex_box, with the far set S' seeded by the k face
  // triangles with the worst cones from v (k = 1 .. all, ties in triangle
  // order) and grown until every rim tetrahedron is positive; among every
  // seed and every w, the best worst tet_shape over the box wins (the first
  // on ties), and it is taken only if strictly better than `single`. Every
  // tetrahedron is positive by exact orient3d (w sees S', v sees the rest
  // and every rim tetrahedron is checked), so the rebuild loop never reacts
  // to it; floats only choose between valid constructions. Not recorded in
  // two_apex_points() (that list decides mesh_boxes' second run).
  bool flat_two_apex_box(std::int32_t leaf, const std::vector<Tri>& tris, int v, double single) {
    const Vec3 V = book_.point(v);
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t n = 0; n < tris.size(); ++n)
      order.push_back({tet_shape(book_.point(tris[n][0]), book_.point(tris[n][2]), book_.point(tris[n][1]), V), n});
    std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    TwoApex best;
    std::vector<char> far0(tris.size(), 0);
    for (const auto& [shape, n] : order) {
      far0[n] = 1;
      const TwoApex c = best_two_apex(leaf, tris, v, far0);
      if (c.shape < best.shape) best = c;
    }
    if (!(best.shape < single)) return false;
    make_two_apex(leaf, tris, v, best);
    return true;
  }

  // Edge boxes whose worst single-apex cone is flatter than this (tet_shape,
  // about twice the aspect ratio) try flat_two_apex_box. A float threshold
  // that only decides whether to look for another valid construction.
  static constexpr double kFlatCone = 4096;

  bool seen(const Tri& t, Vec3 apex) const {
    return orient3d(book_.point(t[0]), book_.point(t[2]), book_.point(t[1]), apex) == Sign::Positive;
  }

  // The best two-point construction for far-set seed far0 (see two_apex_box):
  // shape +infinity when no candidate w is valid.
  struct TwoApex {
    double shape = std::numeric_limits<double>::infinity();
    GridPoint w{};
    std::vector<char> far;
  };
  TwoApex best_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v, const std::vector<char>& far0) {
    const BoxKey<3>& key = tree_.key(leaf);
    TwoApex best;
    const std::int64_t q = key.fine_side() / 4;
    if (q * 4 != key.fine_side()) return best;
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
    const GridPoint lo = key_corner(key, 0);
    for (std::int64_t i = 1; i <= 3; ++i)
      for (std::int64_t j = 1; j <= 3; ++j)
        for (std::int64_t k = 1; k <= 3; ++k) {
          GridPoint g = lo;
          g.f[0] += i * q;
          g.f[1] += j * q;
          g.f[2] += k * q;
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
  static std::vector<std::pair<int, int>> rim_of(const std::vector<Tri>& tris,
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
  void make_two_apex(std::int32_t leaf, const std::vector<Tri>& tris, int v, const TwoApex& c) {
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
  Vec3 apex_on_edge(const std::vector<Tri>& tris, Vec3 a, Vec3 b, const std::vector<int>& ends, Vec3 mid, double t0,
                    double t1) {
    const Vec3 p0 = ends.size() == 2 ? book_.point(ends[0]) : a + t0 * (b - a);
    const Vec3 p1 = ends.size() == 2 ? book_.point(ends[1]) : a + t1 * (b - a);
    auto worst = [&](Vec3 apex) { return worst_cone(tris, apex); };
    Vec3 best = round_onto_segment(a, b, mid);
    double best_shape = worst(best);
    // A midpoint with a non-positive cone is kept: the warp that caused it
    // is found and frozen by the rebuild loop (mesh_boxes), as before.
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

  // The united box B of P vertex `vertex` (2x2x2 leaves of `leaf`'s size,
  // extending below the leaf along the axes of `block`), coned from the vertex.
  void vertex_box(std::int32_t leaf, int vertex, std::uint8_t block) {
    const BoxKey<3>& key = tree_.key(leaf);
    const std::int64_t fs = key.fine_side();
    const GridPoint lo = united_lo(key, block);
    const Vec3 p = domain_.plc.vertices.at(static_cast<std::size_t>(vertex));
    {
      GridPoint hi = lo;
      for (int a = 0; a < 3; ++a) hi.f[static_cast<std::size_t>(a)] += 2 * fs;
      const Vec3 L = grid_coordinates(tree_, lo), H = grid_coordinates(tree_, hi);
      if (!(L.x < p.x && p.x < H.x && L.y < p.y && p.y < H.y && L.z < p.z && p.z < H.z))
        throw InternalError("tet3d: vertex " + std::to_string(vertex) + " is not inside its united box (leaf " +
                            std::to_string(leaf) + ")");
    }
    const BoxFaces faces = squares_.faces_of(BoxKind::Vertex, vertex);
    std::vector<FaceSquare> squares;
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) united_face_squares(key, block, axis, upper, corners_, squares);
    const std::vector<Sign> hints = vertex_box_hints(squares, faces);
    std::vector<Tri> tris;
    for (std::size_t i = 0; i < squares.size(); ++i) {
      const std::size_t first = tris.size();
      squares_.triangulate(squares[i], faces, tris, hints[i]);
      if (!squares[i].upper)
        for (std::size_t k = first; k < tris.size(); ++k) std::swap(tris[k][1], tris[k][2]);
    }
    const VertexKey vk{VertexKind::PVertex, {}, {}, vertex};
    const int v = book_.id(vk, [&] { return p; });
    for (const Tri& t : tris) cone(leaf, t, v);
    ++out_.stats.vertex;
  }

  // For the squares of a united box that meet no face of v's cone: inside or
  // outside P, from a ring point shared with a square that meets a face,
  // whose local model (square_cases.hpp local_status) is exact there; then
  // propagated over the box surface through shared ring points (a square
  // meeting no face lies wholly inside or outside, so all its ring points
  // share its status). Zero where nothing is known (the dispatcher then
  // falls back to locate()).
  std::vector<Sign> vertex_box_hints(const std::vector<FaceSquare>& squares, const BoxFaces& faces) {
    std::vector<SquareDispatcher::Incidence> inc;
    std::vector<std::vector<GridPoint>> rings;
    std::unordered_map<GridPoint, Sign, GridPointHash> status;
    for (const FaceSquare& s : squares) {
      inc.push_back(squares_.incidences(s, faces));
      rings.push_back(square_ring(s, corners_));
    }
    for (std::size_t i = 0; i < squares.size(); ++i) {
      const SquareDispatcher::Incidence& m = inc[i];
      if (m.none() || !m.vertices.empty() || m.edges.size() > 1 || m.facets.size() > 2) continue;
      if (m.facets.size() == 2 && squares_.edge_of_facets(m.facets[0], m.facets[1]) < 0) continue;
      for (const GridPoint& p : rings[i]) {
        const Sign st = squares_.local_status(m, grid_coordinates(tree_, p));
        if (st != Sign::Zero) status.emplace(p, st);
      }
    }
    std::vector<Sign> hint(squares.size(), Sign::Zero);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = 0; i < squares.size(); ++i) {
        if (!inc[i].none() || hint[i] != Sign::Zero) continue;
        for (const GridPoint& p : rings[i]) {
          const auto it = status.find(p);
          if (it == status.end()) continue;
          hint[i] = it->second;
          break;
        }
        if (hint[i] == Sign::Zero) continue;
        changed = true;
        for (const GridPoint& p : rings[i]) status.emplace(p, hint[i]);
      }
    }
    return hint;
  }

  // Two-facet box (§4.5.5; see facet_boxes.hpp for the construction).
  void two_facet_box(std::int32_t leaf, int edge) {
    const EdgeCone& ec = squares_.cone(edge);
    const BoxKey<3>& key = tree_.key(leaf);
    std::vector<Tri> tris;
    box_tris(key, squares_.faces_of(BoxKind::TwoFacet, edge), tris);
    const GridPoint centre = key_centre(key);
    const Vec3 C = grid_coordinates(tree_, centre);
    const double h = tree_.side(leaf);
    const FacetPlane* pl[2] = {&ec.f(), &ec.g()};
    const auto chord0 = chords(leaf, tris, *pl[0]);
    const auto chord1 = chords(leaf, tris, *pl[1]);
    if (chord0.empty() || chord1.empty())
      throw InternalError("tet3d: two-facet box " + std::to_string(leaf) + " without both facets on its faces");
    // The centre strictly on P's side of both planes: for a convex edge it is
    // inside P, for a reflex one in the kernel H_F ∩ H_G of the star-shaped
    // P ∧ b; it sees every boundary triangle from inside.
    const bool kernel = pl[0]->side(C) == Sign::Negative && pl[1]->side(C) == Sign::Negative;
    const bool far = std::fabs(pl[0]->distance(C)) >= h / 4 && std::fabs(pl[1]->distance(C)) >= h / 4;
    if (kernel && (far || !ec.convex())) {
      const int v = centre_vertex(centre);
      for (const Tri& t : tris) cone(leaf, t, v);
      fan(leaf, chord0, *pl[0], VertexKind::TwoFacetCentre, centre, v);
      fan(leaf, chord1, *pl[1], VertexKind::TwoFacetCentre, centre, v);
      ++out_.stats.two_facet_centre;
      out_.stats.two_facet_reflex += ec.convex() ? 0 : 1;
      ++out_.stats.two_facet;
      return;
    }
    if (!ec.convex())
      throw InternalError("tet3d: two-facet box " + std::to_string(leaf) + " at reflex edge " + std::to_string(edge) +
                          " with its centre outside the kernel (not done)");
    // The apex: the vertex mean of the polygon of the facet whose plane is
    // nearer the box centre, or another central point of either polygon when
    // it makes the better valid box (two_facet_apex).
    const Chords* ch[2] = {&chord0, &chord1};
    const int near = std::fabs(pl[0]->distance(C)) <= std::fabs(pl[1]->distance(C)) ? 0 : 1;
    const TwoFacetApex apex = two_facet_apex(tris, pl, ch, near);
    out_.stats.two_facet_apex_farther += apex.facet != near ? 1 : 0;
    const FacetPlane& f = *pl[apex.facet];
    const FacetPlane& g = *pl[1 - apex.facet];
    const Chords& chord_g = *ch[1 - apex.facet];
    const int v = book_.id({VertexKind::TwoFacetApex, centre, {}, f.facet()}, [&] { return apex.at; });
    for (const Tri& t : tris)
      if (!(on_facet(t[0], f) && on_facet(t[1], f) && on_facet(t[2], f))) cone(leaf, t, v);
    fan(leaf, chord_g, g, VertexKind::TwoFacetCentre, centre, v);
    ++out_.stats.two_facet;
  }

  void set_job(std::size_t j, const BoxJob& job) {
    job_ = static_cast<std::int32_t>(j);
    job_box_ = job;
  }
  void collect_bad() { collect_ = true; }
  // Edge boxes whose apex on E does not see every face triangle are made
  // from two cone points (two_apex_box) only when allowed; either way
  // two_apex_points() lists the box vertices (grid points, repeats allowed)
  // of every box that had a valid such construction.
  void allow_two_apex(bool on) { two_apex_ = on; }
  const std::vector<GridPoint>& two_apex_points() const { return two_apex_points_; }
  // The largest tet_shape over the tetrahedra made so far (+infinity for one
  // flat in floating point).
  double worst_shape() const {
    double worst = 0;
    for (const auto& t : out_.mesh.tetrahedra)
      worst = std::max(worst, tet_shape(book_.point(t[0]), book_.point(t[1]), book_.point(t[2]), book_.point(t[3])));
    return worst;
  }
  const std::vector<GridPoint>& bad() const { return bad_; }
  // Per bad() point: bit a set when it lies on the low face of the inverted
  // tetrahedron's box with normal axis a, bit 3 + a on its high face.
  const std::vector<std::uint8_t>& bad_axes() const { return bad_axes_; }
  // The jobs of the inverted tetrahedra (collect mode), in order, repeats allowed.
  const std::vector<std::int32_t>& bad_jobs() const { return bad_jobs_; }

  void count_squares() {
    out_.stats.squares_nothing = squares_.count(SquareCase::Nothing);
    out_.stats.squares_a = squares_.count(SquareCase::A);
    out_.stats.squares_c = squares_.count(SquareCase::C);
    out_.stats.squares_bd = squares_.count(SquareCase::BD);
    out_.stats.vertex_squares_located = squares_.located();
    out_.stats.vertex_squares_by_neighbours = squares_.located_by_neighbours();
  }

  BoxMesh finish() {
    // The book is not used after this: its tables are moved, not copied.
    out_.mesh.vertices = book_.take_points();
    out_.keys = book_.take_keys();
    out_.mesh.tetrahedron_markers.assign(out_.mesh.tetrahedra.size(), 0);
    return std::move(out_);
  }

 private:
  using Chords = std::map<std::pair<int, int>, std::pair<int, int>>;

  // π-triangles of the given squares, right-hand normal out of the box
  // (the dispatcher gives +n; a lower face's outward normal is -n).
  void square_tris(const std::vector<FaceSquare>& squares, const BoxFaces& faces, bool upper, std::vector<Tri>& tris) {
    const std::size_t first = tris.size();
    for (const FaceSquare& s : squares) squares_.triangulate(s, faces, tris);
    if (!upper)
      for (std::size_t i = first; i < tris.size(); ++i) std::swap(tris[i][1], tris[i][2]);
  }

  void box_tris(const BoxKey<3>& key, const BoxFaces& faces, std::vector<Tri>& tris) {
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) {
        std::vector<FaceSquare> squares;
        face_squares(key, axis, upper, corners_, squares);
        square_tris(squares, faces, upper, tris);
      }
  }

  // Edges of face triangles on F: the boundary of the polygon F ∩ b, keyed
  // by (smaller id, larger id), each kept with the direction a -> b it has
  // in its face triangle. Every such edge lies on the face triangles' side
  // of one box face, so it is in exactly one of them (the part of a face
  // beyond F yields no triangles).
  Chords chords(std::int32_t leaf, const std::vector<Tri>& tris, const FacetPlane& plane) const {
    Chords chord;
    for (const Tri& t : tris)
      for (int i = 0; i < 3; ++i) {
        const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
        if (!on_facet(a, plane) || !on_facet(b, plane)) continue;
        if (!chord.emplace(std::pair{std::min(a, b), std::max(a, b)}, std::pair{a, b}).second)
          throw InternalError("tet3d: edge on F in two face triangles of leaf " + std::to_string(leaf));
      }
    return chord;
  }

  // The mean of the polygon's vertices (a point of the relative interior of
  // the convex polygon F ∩ b; not yet rounded onto F).
  Vec3 vertex_mean(const Chords& chord) const {
    std::set<int> poly;
    for (const auto& [edge, directed] : chord) poly.insert({edge.first, edge.second});
    Vec3 mean;
    for (const int p : poly) mean = mean + book_.point(p);
    return (1.0 / static_cast<double>(poly.size())) * mean;
  }

  // The vertex mean rounded onto F.
  Vec3 polygon_point(const Chords& chord, const FacetPlane& plane) const {
    return plane.settle(vertex_mean(chord), dominant_axis(plane.normal()));
  }

  // The worst tet_shape of the cones from `apex` over the face triangles
  // (those with all three vertices on `skip` left out, when given); +infinity
  // if one of them is not positive by exact orient3d.
  double worst_cone(const std::vector<Tri>& tris, Vec3 apex, const FacetPlane* skip = nullptr) const {
    double w = 0;
    for (const Tri& t : tris) {
      if (skip != nullptr && on_facet(t[0], *skip) && on_facet(t[1], *skip) && on_facet(t[2], *skip)) continue;
      const Vec3 x = book_.point(t[0]), y = book_.point(t[2]), z = book_.point(t[1]);
      if (orient3d(x, y, z, apex) != Sign::Positive) return std::numeric_limits<double>::infinity();
      w = std::max(w, tet_shape(x, y, z, apex));
    }
    return w;
  }

  // The worst tet_shape of the fan of F ∩ b (its chords) from g, coned to
  // `apex` (the tetrahedra of fan); with `exact`, +infinity if one of them is
  // not positive by exact orient3d.
  double worst_fan(const Chords& chord, Vec3 g, Vec3 apex, bool exact) const {
    double w = 0;
    for (const auto& [edge, directed] : chord) {
      const Vec3 a = book_.point(directed.first), b = book_.point(directed.second);
      if (exact && orient3d(a, b, g, apex) != Sign::Positive) return std::numeric_limits<double>::infinity();
      w = std::max(w, tet_shape(a, b, g, apex));
    }
    return w;
  }

  // The apex of a two-facet box at a convex edge (our choice within §4.5.5,
  // docs/ALGORITHM.md §12.5 Gap (1)): a central point of F ∩ b for one of
  // the two facets F, coned to the face triangles not on F, with the other
  // facet's polygon fanned from its vertex mean (as fan with no bar).
  // The first candidate is `near` (the facet whose plane is nearer the box
  // centre) with its vertex mean (polygon_point); the others are the other
  // central points of that polygon (central_points), then the same for the
  // other facet. A later candidate is taken only if every one of its
  // tetrahedra is positive by exact orient3d and its worst tet_shape is
  // strictly better; the float shapes only choose between valid
  // constructions (an invalid first candidate counts as +infinity, exactly
  // decided), and when none is valid the first is kept and the rebuild loop
  // (mesh_boxes) freezes the warp that caused it, as before. Why both:
  // the nearer plane's polygon can be a sliver lying almost in a box face
  // (every-run seed 197: 0.002 h from face x = 1, whose warped corners then
  // made its cones flat or inverted); the vertex mean is pulled towards a
  // face split into small squares, and can lie almost on the line of a chord
  // of that face (harsh seed 17: a 5 degree wedge's box beside boxes 16 and
  // 32 times smaller, aspect 466,599).
  struct TwoFacetApex {
    int facet = 0;  // index into the two planes
    Vec3 at;        // on that facet's plane (rounded onto it)
  };
  TwoFacetApex two_facet_apex(const std::vector<Tri>& tris, const FacetPlane* const pl[2], const Chords* const ch[2],
                              int near) const {
    TwoFacetApex best{near, polygon_point(*ch[near], *pl[near])};
    double best_shape = std::numeric_limits<double>::infinity();
    for (const int i : {near, 1 - near}) {
      const FacetPlane& f = *pl[i];
      const FacetPlane& g = *pl[1 - i];
      const Vec3 fan_point = polygon_point(*ch[1 - i], g);
      for (const Vec3& apex : central_points(*ch[i], f)) {
        const double shape = std::max(worst_cone(tris, apex, &f), worst_fan(*ch[1 - i], fan_point, apex, true));
        if (shape < best_shape) {
          best = {i, apex};
          best_shape = shape;
        }
      }
    }
    return best;
  }

  // §4.5.4 asks for "a centrally located point" of F ∩ I(b). The vertex mean
  // is pulled towards the side with more vertices: on a long thin polygon
  // (F clipping a box edge, one face beside it split into small squares:
  // bounded random seed 58, docs/ALGORITHM.md §12.5) it lies almost on the
  // line of a chord and that fan tetrahedron is flat (aspect 16,433). So when
  // the worst fan tetrahedron from the mean is worse (tet_shape, compared
  // only) than `bar` (the worst cone of the box: only then is the fan the
  // box's weakest part), the polygon's area centroid and its boundary's
  // length-weighted centroid are tried, each rounded onto F and taken only if
  // every one of its fan tetrahedra is positive by exact orient3d and its
  // worst is better. Returns the point (rounded onto F).
  Vec3 fan_centre(const Chords& chord, const FacetPlane& plane, int v, double bar) const {
    const Vec3 apex = book_.point(v);
    auto worst = [&](Vec3 g, bool exact) { return worst_fan(chord, g, apex, exact); };
    Vec3 best = polygon_point(chord, plane);
    if (!(bar < std::numeric_limits<double>::infinity())) return best;
    double best_shape = worst(best, false);
    if (!(best_shape > bar)) return best;
    const std::vector<Vec3> candidates = central_points(chord, plane);
    for (std::size_t k = 1; k < candidates.size(); ++k) {
      const double s = worst(candidates[k], true);
      if (s < best_shape) {
        best = candidates[k];
        best_shape = s;
      }
    }
    return best;
  }

  // Central points of the convex polygon F ∩ b (its chords), each rounded
  // onto F: [0] the vertex mean (polygon_point), then the area centroid (the
  // fan triangles (a, b, mean) weighted by their signed area along F's
  // normal: the chords turn one way around F ∩ b) and the boundary's
  // length-weighted centroid (chord midpoints), when defined.
  std::vector<Vec3> central_points(const Chords& chord, const FacetPlane& plane) const {
    const int axis = dominant_axis(plane.normal());
    const Vec3 mean = vertex_mean(chord);
    std::vector<Vec3> out = {plane.settle(mean, axis)};
    Vec3 area_sum, length_sum;
    double area = 0, length = 0;
    for (const auto& [edge, directed] : chord) {
      const Vec3 a = book_.point(directed.first), b = book_.point(directed.second);
      const double s = dot(cross(a - mean, b - mean), plane.normal());
      area_sum = area_sum + (s / 3) * (a + b + mean);
      area += s;
      const double l = norm(b - a);
      length_sum = length_sum + (l / 2) * (a + b);
      length += l;
    }
    if (area != 0) out.push_back(plane.settle((1 / area) * area_sum, axis));
    if (length > 0) out.push_back(plane.settle((1 / length) * length_sum, axis));
    return out;
  }

  // Fan of F ∩ b from its central point g, coned to v. P ∧ b is convex and
  // bounded by the outward face triangles and F ∩ b, so edge a -> b of a face
  // triangle runs b -> a in F ∩ b oriented outward (away from v): (b, a, g) is
  // an outward triangle with v inside, hence (a, b, g, v) is positive.
  // `bar` (facet boxes): see fan_centre; +infinity keeps the vertex mean.
  void fan(std::int32_t leaf, const Chords& chord, const FacetPlane& plane, VertexKind kind, const GridPoint& centre,
           int v, double bar = std::numeric_limits<double>::infinity()) {
    const VertexKey gk{kind, centre, {}, plane.facet()};
    const int g = book_.id(gk, [&] { return fan_centre(chord, plane, v, bar); });
    for (const auto& [edge, directed] : chord) tet(leaf, "fan", directed.first, directed.second, g, v);
  }

  int grid(const GridPoint& p) { return grid_vertex(p, tree_, warps_, book_); }
  // Box centres are never box vertices, so never warped.
  int centre_vertex(const GridPoint& p) {
    return book_.id(grid_key(p), [&] { return grid_coordinates(tree_, p); });
  }

  bool on_facet(int id, const FacetPlane& plane) const {
    const VertexKey& k = book_.key(id);
    if (on_its_facet(k)) return k.facet == plane.facet();
    return k.kind == VertexKind::Grid && plane.side(book_.point(id)) == Sign::Zero;
  }

  // Appends (a, b, c, d), positively oriented by construction (mesh.hpp: d
  // on the side of the right-hand normal of (a, b, c)). Exact orient3d on the
  // final (rounded or warped) coordinates must agree; a flat or inverted
  // tetrahedron is a bug (or a warp that bent a face past the apex) and
  // throws naming the leaf, never flipped (ALGORITHM.md §12.2, rule 3).
  void tet(std::int32_t leaf, const char* what, int a, int b, int c, int d) {
    const Sign s = orient3d(book_.point(a), book_.point(b), book_.point(c), book_.point(d));
    if (s != Sign::Positive && warps_ != nullptr && collect_) {
      // A warp bent a face past the apex: the moved grid points this
      // tetrahedron depends on are reported, frozen and the mesh rebuilt
      // (mesh_boxes); none found: a bug, thrown below.
      if (report_moved({a, b, c, d})) {
        bad_jobs_.push_back(job_);
        return;
      }
    }
    if (s != Sign::Positive)
      throw InternalError(std::string("tet3d: ") + what + " tetrahedron of leaf " + std::to_string(leaf) + " is " +
                          (s == Sign::Zero ? "flat" : "inverted"));
    out_.mesh.tetrahedra.push_back({a, b, c, d});
    out_.tet_leaf.push_back(leaf);
    out_.tet_job.push_back(job_);
  }

  // The moved grid points the vertices depend on, appended to bad_: those
  // their keys name (a warped box vertex or square centre, the ends of a
  // crossed ring segment, a clipped ring point); for a point constructed on
  // a square (chord midpoint, projections, Case B crossing: keyed by the
  // square's centre only) the moved ring points of that square of the job's
  // box; if still none (points constructed from the whole box: facet
  // polygon centres), every moved ring point of the job's box. Returns
  // whether any was found.
  bool report_moved(std::initializer_list<int> vertices) {
    const std::size_t before = bad_.size();
    std::vector<FaceSquare> squares;
    job_squares(tree_, corners_, job_box_, squares);
    // The job's box (a united vertex box spans 2x2x2 leaves): bad_axes_ gets
    // bit a when g lies on its low face along axis a, bit 3 + a on its high
    // face (warp.cpp, `second_only`).
    const BoxKey<3>& key = tree_.key(job_box_.leaf);
    const bool united = job_box_.kind == BoxKind::Vertex;
    const GridPoint lo = united ? united_lo(key, job_box_.block) : key_corner(key, 0);
    const std::int64_t side = (united ? 2 : 1) * key.fine_side();
    auto add = [&](const GridPoint& g) {
      std::uint8_t axes = 0;
      for (std::size_t a = 0; a < 3; ++a) {
        if (g.f[a] == lo.f[a]) axes = static_cast<std::uint8_t>(axes | (1u << a));
        if (g.f[a] == lo.f[a] + side) axes = static_cast<std::uint8_t>(axes | (8u << a));
      }
      bad_.push_back(g);
      bad_axes_.push_back(axes);
    };
    auto report_square = [&](const FaceSquare& sq) {
      for (const GridPoint& g : square_ring(sq, corners_))
        if (warps_->moved(g)) add(g);
    };
    for (const int v : vertices) {
      const VertexKey& k = book_.key(v);
      for (const GridPoint& g : {k.p, k.q})
        if (warps_->moved(g)) add(g);
      if (k.kind == VertexKind::Grid || k.kind == VertexKind::Warped || k.kind == VertexKind::PVertex ||
          k.kind == VertexKind::EdgeMidpoint)
        continue;
      for (const FaceSquare& sq : squares)
        if (sq.centre() == k.p) report_square(sq);
    }
    if (bad_.size() == before)
      for (const FaceSquare& sq : squares) report_square(sq);
    return bad_.size() > before;
  }

  // The cone from an apex inside the box over a face triangle with outward
  // normal: the reversed triangle followed by the apex is positive.
  void cone(std::int32_t leaf, const Tri& t, int apex) { tet(leaf, "cone", t[0], t[2], t[1], apex); }

  bool key_less(int a, int b) const { return book_.key(a) < book_.key(b); }

  // Cuts quad (a, b, c, d) (cyclic) into two triangles by the diagonal from its smallest key.
  std::array<Tri, 2> split_quad(int a, int b, int c, int d) const {
    std::array<int, 4> q{a, b, c, d};
    std::size_t lo = 0;
    for (std::size_t m = 1; m < 4; ++m)
      if (key_less(q[m], q[lo])) lo = m;
    const int p0 = q[lo], p1 = q[(lo + 1) % 4], p2 = q[(lo + 2) % 4], p3 = q[(lo + 3) % 4];
    return {Tri{p0, p1, p2}, Tri{p0, p2, p3}};
  }

  // §4.5.4 third case: the cone from the centre (beyond F) over face triangle
  // t, clipped by F. Orientations by construction: t is outward, so every
  // other prism vertex is on its inner side; top[i] lies on the segment from
  // t[i] towards the centre, so the top triangle in index order is a shrunk
  // copy of t (same normal, pointing from the top towards t), and a side
  // (t[i], t[j], top[j], top[i]) with j = i + 1 lies in the plane of the
  // centre, t[i] and t[j], its right-hand normal pointing into the prism
  // (edge t[i] -> t[j] runs the other way in the outward surface).
  void prism(std::int32_t leaf, const Tri& t, const GridPoint& centre, Vec3 C, const FacetPlane& plane) {
    std::array<int, 3> top{};
    int shared = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      if (on_facet(t[i], plane)) {
        top[i] = t[i];
        ++shared;
        continue;
      }
      const VertexKey& tk = book_.key(t[i]);
      if (tk.kind != VertexKind::Grid && tk.kind != VertexKind::Warped)
        throw InternalError("tet3d: prism bottom vertex off F is not a box vertex or square centre");
      const VertexKey ck{VertexKind::BoxClip, centre, tk.p, plane.facet()};
      const Vec3 p = book_.point(t[i]);
      top[i] = book_.id(ck, [&] { return plane.crossing(C, p); });
    }
    if (shared == 3) throw InternalError("tet3d: face triangle lies on F in leaf " + std::to_string(leaf));
    if (shared == 2) {
      for (std::size_t i = 0; i < 3; ++i)
        if (top[i] != t[i]) cone(leaf, t, top[i]);
      return;
    }
    if (shared == 1) {
      std::size_t s = 0;
      while (top[s] != t[s]) ++s;
      const int apex = t[s], b1 = t[(s + 1) % 3], b2 = t[(s + 2) % 3];
      // The side quad's triangles have inward normals and apex on their inner side.
      for (const Tri& q : split_quad(b1, b2, top[(s + 2) % 3], top[(s + 1) % 3]))
        tet(leaf, "prism", q[0], q[1], q[2], apex);
      return;
    }
    // Full prism: the smallest of its six vertices is the apex of the two
    // quads through it; cut off the tetrahedron of the opposite triangle's
    // edge... (bottom t, top `top`).
    std::array<int, 6> all{t[0], t[1], t[2], top[0], top[1], top[2]};
    std::size_t m = 0;
    for (std::size_t i = 1; i < 6; ++i)
      if (key_less(all[i], all[m])) m = i;
    const std::size_t i0 = m % 3, i1 = (i0 + 1) % 3, i2 = (i0 + 2) % 3;
    const bool bottom = m < 3;
    // The minimum vertex and the whole triangle (top or bottom) it is not in.
    const int apex = all[m];
    const int o0 = bottom ? top[i0] : t[i0], o1 = bottom ? top[i1] : t[i1], o2 = bottom ? top[i2] : t[i2];
    // The top's normal points towards the bottom, t's away from the top.
    if (bottom)
      tet(leaf, "prism", o0, o1, o2, apex);
    else
      tet(leaf, "prism", o0, o2, o1, apex);
    // Remaining pyramid: apex over the side quad t[i1] t[i2] top[i2] top[i1].
    for (const Tri& q : split_quad(t[i1], t[i2], top[i2], top[i1])) tet(leaf, "prism", q[0], q[1], q[2], apex);
  }

  const OctTree& tree_;
  const CornerSet& corners_;
  const Domain3& domain_;
  const WarpTable* warps_;
  std::int32_t job_ = -1;
  BoxJob job_box_;
  bool collect_ = false;
  bool two_apex_ = false;
  std::vector<GridPoint> two_apex_points_;  // two_apex_points()
  std::vector<GridPoint> bad_;  // moved grid points of inverted tetrahedra (collect_ mode)
  std::vector<std::uint8_t> bad_axes_;  // parallel to bad_ (bad_axes())
  std::vector<std::int32_t> bad_jobs_;
  PointBook book_;
  SquareDispatcher squares_{tree_, corners_, domain_, book_, warps_};
  BoxMesh out_;
};

}  // namespace

namespace {

void run_jobs(Assembler& a, const OctTree& tree, std::span<const BoxJob> jobs) {
  for (std::size_t ji = 0; ji < jobs.size(); ++ji) {
    const BoxJob& j = jobs[ji];
    a.set_job(ji, j);
    if (!tree.is_leaf(j.leaf)) throw InternalError("tet3d: node " + std::to_string(j.leaf) + " is not a leaf");
    switch (j.kind) {
      case BoxKind::FromFacet:
        if (j.facet < 0)
          a.empty_box(j.leaf);
        else
          a.facet_box(j.leaf, j.facet);
        break;
      case BoxKind::Empty: a.empty_box(j.leaf); break;
      case BoxKind::Facet: a.facet_box(j.leaf, j.apex); break;
      case BoxKind::Edge: a.edge_box(j.leaf, j.apex); break;
      case BoxKind::Vertex: a.vertex_box(j.leaf, j.apex, j.block); break;
      case BoxKind::TwoFacet: a.two_facet_box(j.leaf, j.apex); break;
    }
  }
}

}  // namespace

namespace {

// The candidate stage's free blocks (the candidate list is a few large
// arrays since warp_candidates.hpp, but the square scratch and the hash
// nodes of the table passes are small blocks) stay in glibc's heap, and the
// pass after them allocates its tables as fresh mappings, so the freed pages
// would count twice in the peak (plate_holes without the trim: +3.4 MB). They go back to the system here (glibc only; elsewhere
// a no-op).
void release_free_heap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace

namespace {

// One run of the warped (or unwarped) box meshing; `two_apex` allows the
// two-cone-point edge boxes; `wanted` gets the box vertices of the boxes
// for which a trial or the final pass had a valid one (allowed or not),
// `held` the grid points the rebuild loop froze or limited to their box
// faces.
BoxMesh mesh_boxes_pass(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                        std::span<const BoxJob> jobs, const BoxMeshOptions& options, bool two_apex,
                        std::unordered_set<GridPoint, GridPointHash>& wanted,
                        std::unordered_set<GridPoint, GridPointHash>& held) {
  WarpTable warps;
  std::int64_t rebuilds = 0;
  // The warped run's trial pass (collect mode) that inverted nothing: it made
  // exactly the tetrahedra the final pass would make (same table, same job
  // order; collect mode differs only where a tetrahedron inverts), so it is
  // the result and the final pass is skipped.
  std::unique_ptr<Assembler> done;
  if (options.warp) {
    warps = warp_box_vertices(tree, corners, domain, warp_candidates(tree, corners, domain, jobs), nullptr,
                              options.reflex_copies);
    release_free_heap();
    // A warp may bend a box face past a cone apex near it (an apex on a P
    // edge or facet close to the box face; the thesis's first pass and
    // vertex centring keep them apart, not done here): the moved points of
    // every inverted tetrahedron are frozen (left in place, counted) and the
    // table rebuilt, until no tetrahedron inverts. Deterministic. The
    // candidates (plate_holes: ~36 MB of a 130 MB peak) are not kept through
    // the trial passes: a rebuild makes them again (same list).
    std::unordered_set<GridPoint, GridPointHash> frozen;
    std::unordered_map<GridPoint, std::uint8_t, GridPointHash> second_only;
    std::vector<EdgeBoxBounds> edge_boxes;
    std::set<std::int32_t> shifted_jobs;
    for (int round = 0; round < 16; ++round) {
      auto trial = std::make_unique<Assembler>(tree, corners, domain, &warps);
      trial->collect_bad();
      trial->allow_two_apex(two_apex);
      run_jobs(*trial, tree, jobs);
      wanted.insert(trial->two_apex_points().begin(), trial->two_apex_points().end());
      if (trial->bad().empty()) {
        done = std::move(trial);
        break;
      }
      ++rebuilds;
      // Edge boxes with an inverted cone get their faces through a close
      // box edge translated (warp.cpp, face translations; once per box) and
      // the table is rebuilt without freezing anything; when no such box is
      // new, the moved points of the inverted tetrahedra are frozen.
      bool translated = false;
      for (const std::int32_t ji : trial->bad_jobs()) {
        const BoxJob& j = jobs[static_cast<std::size_t>(ji)];
        if (j.kind != BoxKind::Edge || !shifted_jobs.insert(ji).second) continue;
        edge_boxes.push_back({key_corner(tree.key(j.leaf), 0), key_corner(tree.key(j.leaf), 7), j.apex});
        translated = true;
      }
      if (!translated) {
        // A point reported for the first time keeps the part of its second
        // pass within the inverted tetrahedra's box faces (warp.cpp,
        // `second_only`); reported again, it is frozen.
        std::unordered_map<GridPoint, std::uint8_t, GridPointHash> now;
        for (std::size_t i = 0; i < trial->bad().size(); ++i) now[trial->bad()[i]] |= trial->bad_axes()[i];
        for (const auto& [g, axes] : now)
          if (!second_only.emplace(g, axes).second) frozen.insert(g);
      }
      trial.reset();
      warps = warp_box_vertices(tree, corners, domain, warp_candidates(tree, corners, domain, jobs), &frozen,
                                options.reflex_copies, edge_boxes, &second_only);
      release_free_heap();
    }
    // One decision per shared face (docs/ALGORITHM.md §12.5): a reported
    // point keeps only the part of its second pass within the reporting
    // box's faces, which leaves a face near a P edge unwarped. Its move out of
    // the reporting box (away from that box's apex) helps that box but bends
    // the face of the box across, whose own apex may lie near it (every-run
    // seed 30: 1,833 -> 393; seed 100: 304 -> 675). Both tables give valid
    // meshes when the trial inverts nothing (exact orient3d); the one with
    // the better worst tetrahedron (tet_shape, only compared) is kept, the
    // table without those moves on a tie. Runs without such a move are
    // unchanged.
    // The finished trial is dropped before the other table is built (the
    // candidates and a mesh are a large part of the peak memory); when that
    // table loses, the final pass below remakes this mesh.
    if (done && warps.out_of_face_left > 0) {
      const double worst_before = done->worst_shape();
      done.reset();
      release_free_heap();
      WarpTable wider = warp_box_vertices(tree, corners, domain, warp_candidates(tree, corners, domain, jobs),
                                          &frozen, options.reflex_copies, edge_boxes, &second_only, true);
      release_free_heap();
      if (wider.out_of_face > 0) {
        auto trial = std::make_unique<Assembler>(tree, corners, domain, &wider);
        trial->collect_bad();
        trial->allow_two_apex(two_apex);
        run_jobs(*trial, tree, jobs);
        wanted.insert(trial->two_apex_points().begin(), trial->two_apex_points().end());
        if (trial->bad().empty() && trial->worst_shape() < worst_before) {
          warps = std::move(wider);
          done = std::move(trial);
        }
      }
    }
    for (const GridPoint& g : frozen) held.insert(g);
    for (const auto& [g, axes] : second_only) held.insert(g);
  }
  if (!done) {
    done = std::make_unique<Assembler>(tree, corners, domain, options.warp ? &warps : nullptr);
    done->allow_two_apex(two_apex);
    run_jobs(*done, tree, jobs);
    wanted.insert(done->two_apex_points().begin(), done->two_apex_points().end());
  }
  Assembler& a = *done;
  a.count_squares();
  BoxMesh out = a.finish();
  out.warped = static_cast<std::int64_t>(warps.size());
  out.warp_conflicts = warps.conflicts;
  out.warp_bisected = warps.bisected;
  out.warp_fallback = warps.fallback;
  out.warp_reflex_left = warps.reflex_left;
  out.warp_reflex_copied = warps.reflex_copied;
  out.warp_crowded_left = warps.crowded_left;
  out.warp_on_plane = warps.on_plane;
  out.warp_inverting_left = warps.frozen_left;
  out.warp_first_pass = warps.first_pass;
  out.warp_rebuilds = rebuilds;
  out.warp_parallel_left = warps.parallel_left;
  out.warp_parallel = warps.parallel;
  out.warp_centres = warps.centres;
  out.warp_shortened = warps.shortened;
  if (options.keep_warp_table) out.warps = std::make_shared<const WarpTable>(std::move(warps));
  return out;
}

// The worst tet_shape of a finished mesh (only compared) and the index of
// its first tetrahedron of that shape.
std::pair<double, std::size_t> worst_tet_shape(const BoxMesh& m) {
  std::pair<double, std::size_t> worst{0, 0};
  for (std::size_t i = 0; i < m.mesh.tetrahedra.size(); ++i) {
    const auto& t = m.mesh.tetrahedra[i];
    const double s = tet_shape(m.mesh.vertices[static_cast<std::size_t>(t[0])],
                               m.mesh.vertices[static_cast<std::size_t>(t[1])],
                               m.mesh.vertices[static_cast<std::size_t>(t[2])],
                               m.mesh.vertices[static_cast<std::size_t>(t[3])]);
    if (s > worst.first) worst = {s, i};
  }
  return worst;
}

// Whether a tetrahedron of job `job` has a grid point or warped box vertex
// in both `held` and `wanted` (by its key).
bool job_touches(const BoxMesh& m, std::int32_t job, const std::unordered_set<GridPoint, GridPointHash>& held,
                 const std::unordered_set<GridPoint, GridPointHash>& wanted) {
  for (std::size_t i = 0; i < m.mesh.tetrahedra.size(); ++i) {
    if (m.tet_job[i] != job) continue;
    for (const int v : m.mesh.tetrahedra[i]) {
      const VertexKey& k = m.keys[static_cast<std::size_t>(v)];
      if ((k.kind == VertexKind::Grid || k.kind == VertexKind::Warped) && held.count(k.p) > 0 &&
          wanted.count(k.p) > 0)
        return true;
    }
  }
  return false;
}

}  // namespace

// Two-cone-point edge boxes (Assembler::two_apex_box, docs/ALGORITHM.md
// §12.5) keep an edge box valid where the single apex on E inverts, so the
// rebuild loop does not freeze the warp that caused it; but the warp left in
// place can make another box worse than the frozen run does (suite seeds 5,
// 27). So the run without them is made first. Only if the box of that
// run's worst tetrahedron has a point that the rebuild loop held back
// (frozen or kept within its box faces) and that is a vertex of a box which
// had a valid two-point construction in some trial (otherwise a held point
// of a two-point box did not make the worst box, and the second run costs a
// whole run for nothing: bounded seed 58 took 2.7x cpu), the run with them is
// made too, and kept only when its worst tetrahedron (tet_shape, only
// compared; both meshes are valid by exact orient3d) is strictly better.
// Otherwise the first run is remade (not kept meanwhile: a mesh is about
// half the peak memory). Every other run does no extra work and keeps its
// bytes; no run gets a worse worst tetrahedron.
BoxMesh mesh_boxes(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                   std::span<const BoxJob> jobs, const BoxMeshOptions& options) {
  std::unordered_set<GridPoint, GridPointHash> wanted, held;
  BoxMesh single = mesh_boxes_pass(tree, corners, domain, jobs, options, false, wanted, held);
  if (wanted.empty()) return single;
  const auto [single_worst, worst_tet] = worst_tet_shape(single);
  if (single.mesh.tetrahedra.empty() || !job_touches(single, single.tet_job[worst_tet], held, wanted)) return single;
  single = BoxMesh{};
  wanted.clear();
  held.clear();
  release_free_heap();
  BoxMesh two = mesh_boxes_pass(tree, corners, domain, jobs, options, true, wanted, held);
  if (worst_tet_shape(two).first < single_worst) return two;
  two = BoxMesh{};
  release_free_heap();
  return mesh_boxes_pass(tree, corners, domain, jobs, options, false, wanted, held);
}

}  // namespace pqmesh::tet3d
