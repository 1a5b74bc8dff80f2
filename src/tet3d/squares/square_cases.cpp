#include "tet3d/squares/square_cases.hpp"

#include <algorithm>
#include <utility>

#include "plc/edge_topology.hpp"
#include "pqmesh/errors.hpp"
#include "tet3d/squares/square_meets.hpp"

namespace pqmesh::tet3d {

const char* to_string(BoxKind kind) {
  switch (kind) {
    case BoxKind::FromFacet: return "from-facet";
    case BoxKind::Empty: return "empty";
    case BoxKind::Facet: return "facet";
    case BoxKind::Edge: return "edge";
    case BoxKind::Vertex: return "vertex";
    case BoxKind::TwoFacet: return "two-facet";
  }
  return "?";
}

SquareDispatcher::SquareDispatcher(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                                   PointBook& book, const WarpTable* warps)
    : tree_(tree), corners_(corners), domain_(domain), book_(book), warps_(warps) {
  facet_tris_.resize(domain.plc.facets.size());
  for (std::size_t t = 0; t < domain.facet_triangles.size(); ++t)
    facet_tris_[static_cast<std::size_t>(domain.facet_triangle_owner[t])].push_back(static_cast<int>(t));
  pqmesh::detail::VertexIncidence incidence = pqmesh::detail::vertex_incidence(domain);
  vertex_edges_ = std::move(incidence.edges);
  vertex_facets_ = std::move(incidence.facets);
  for (std::size_t e = 0; e < domain.edges.size(); ++e) {
    const DomainEdge& de = domain.edges[e];
    const int f = std::min(de.facets[0], de.facets[1]), g = std::max(de.facets[0], de.facets[1]);
    pair_edges_[{f, g}].push_back(static_cast<int>(e));
  }
  check_collinear_edges();
}

// Two facets in different planes share edges only on the line where the
// planes meet; each such edge's wedge is bounded by the same two planes, and
// its convexity (EdgeCone) is the side of F on which G leaves the line. Were
// it to differ between two of them, the model of a square meeting F and G
// away from both would be ambiguous.
void SquareDispatcher::check_collinear_edges() {
  for (const auto& [pair, list] : pair_edges_) {
    if (list.size() < 2) continue;
    for (const int e : list)
      if (cone(e).convex() != cone(list[0]).convex())
        throw InternalError("tet3d: facets " + std::to_string(pair.first) + " and " + std::to_string(pair.second) +
                            " share convex and reflex edges (" + std::to_string(list[0]) + ", " + std::to_string(e) +
                            ")");
  }
}

BoxFaces SquareDispatcher::faces_of(BoxKind kind, int apex) const {
  BoxFaces b;
  b.kind = kind;
  b.apex = apex;
  switch (kind) {
    case BoxKind::FromFacet:
    case BoxKind::Empty:
      b.kind = BoxKind::Empty;
      b.apex = -1;
      break;
    case BoxKind::Facet:
      b.facets = {apex};
      break;
    case BoxKind::Edge:
    case BoxKind::TwoFacet: {
      const DomainEdge& e = domain_.edges.at(static_cast<std::size_t>(apex));
      if (kind == BoxKind::Edge) b.edges = {apex};
      b.facets = {std::min(e.facets[0], e.facets[1]), std::max(e.facets[0], e.facets[1])};
      break;
    }
    case BoxKind::Vertex:
      b.vertices = {apex};
      b.edges = vertex_edges(apex);
      b.facets = vertex_facets(apex);
      break;
  }
  return b;
}

const FacetPlane& SquareDispatcher::plane(int facet) {
  auto it = planes_.find(facet);
  if (it == planes_.end()) it = planes_.emplace(facet, std::make_unique<FacetPlane>(domain_, facet)).first;
  return *it->second;
}

const EdgeCone& SquareDispatcher::cone(int edge) {
  auto it = cones_.find(edge);
  if (it == cones_.end()) it = cones_.emplace(edge, std::make_unique<EdgeCone>(domain_, edge)).first;
  return *it->second;
}

int SquareDispatcher::edge_of_facets(int f, int g) const {
  const auto it = pair_edges_.find({std::min(f, g), std::max(f, g)});
  if (it == pair_edges_.end()) return -1;
  return it->second[0];  // the smallest id (edges are listed in increasing order)
}

int SquareDispatcher::edge_for_square(int f, int g, const SquareGeometry& geo) const {
  const auto it = pair_edges_.find({std::min(f, g), std::max(f, g)});
  if (it == pair_edges_.end()) return -1;
  if (it->second.size() == 1) return it->second[0];
  const auto& pv = domain_.plc.vertices;
  int found = -1;
  for (const int e : it->second) {
    const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
    if (!segment_meets_square(geo, pv[static_cast<std::size_t>(de.a)], pv[static_cast<std::size_t>(de.b)])) continue;
    if (found >= 0)
      throw InternalError("tet3d: collinear edges " + std::to_string(found) + " and " + std::to_string(e) +
                          " of facets " + std::to_string(f) + " and " + std::to_string(g) +
                          " both meet a square (their common vertex lies on it)");
    found = e;
  }
  return found >= 0 ? found : it->second[0];
}

bool SquareDispatcher::facet_meets(int facet, const SquareGeometry& g) {
  // Cheap exact filter: S strictly on one side of the facet's plane.
  if (!plane_meets(facet, g)) return false;
  const auto& pv = domain_.plc.vertices;
  for (const int t : facet_tris_[static_cast<std::size_t>(facet)]) {
    const auto& tri = domain_.facet_triangles[static_cast<std::size_t>(t)];
    if (triangle_meets_square(g, pv[static_cast<std::size_t>(tri[0])], pv[static_cast<std::size_t>(tri[1])],
                              pv[static_cast<std::size_t>(tri[2])]))
      return true;
  }
  return false;
}

std::string SquareDispatcher::describe(const FaceSquare& s, const BoxFaces& faces, const Incidence& m) const {
  const GridPoint c = s.centre();
  auto list = [](const std::vector<int>& x) {
    std::string r = "{";
    for (std::size_t i = 0; i < x.size(); ++i) r += (i ? ", " : "") + std::to_string(x[i]);
    return r + "}";
  };
  return "square (axis " + std::to_string(s.n) + ", centre " + std::to_string(c.f[0]) + " " + std::to_string(c.f[1]) +
         " " + std::to_string(c.f[2]) + ", side " + std::to_string(s.side) + ") of a " + to_string(faces.kind) +
         " box (apex " + std::to_string(faces.apex) + ") meets vertices " + list(m.vertices) + ", edges " +
         list(m.edges) + ", facets " + list(m.facets);
}

SquareDispatcher::Incidence SquareDispatcher::incidences(const FaceSquare& s, const BoxFaces& faces) {
  const SquareGeometry g = square_geometry(s, tree_);
  const auto& pv = domain_.plc.vertices;
  Incidence m;
  for (const int v : faces.vertices)
    if (square_contains(g, pv[static_cast<std::size_t>(v)])) m.vertices.push_back(v);
  for (const int e : faces.edges) {
    const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
    if (segment_meets_square(g, pv[static_cast<std::size_t>(de.a)], pv[static_cast<std::size_t>(de.b)]))
      m.edges.push_back(e);
  }
  for (const int f : faces.facets) {
    bool meets = false;
    switch (faces.kind) {
      case BoxKind::Facet: meets = plane_meets(f, g); break;
      case BoxKind::Edge:
      case BoxKind::TwoFacet: meets = half_plane_meets(cone(faces.apex), f, g); break;
      case BoxKind::Vertex: meets = sector_meets(faces.apex, f, g); break;
      default: meets = facet_meets(f, g); break;
    }
    if (meets) m.facets.push_back(f);
  }
  return m;
}

// The closed square S meets the facet's plane: its four corners are not all
// strictly on one side (exact orient3d through FacetPlane::side).
bool SquareDispatcher::plane_meets(int facet, const SquareGeometry& g) {
  const FacetPlane& pl = plane(facet);
  int pos = 0, neg = 0;
  for (const Vec3& c : g.corners) {
    const Sign side = pl.side(c);
    pos += side == Sign::Positive;
    neg += side == Sign::Negative;
  }
  return pos < 4 && neg < 4;
}

// F's part of dP near E: the points of F's plane where G's sign is not that of
// P's side of G (convex: P's side or on G, i.e. G <= 0; reflex: G >= 0). The
// section of F's plane with S is a segment, G is affine along it, so it meets
// that part iff one of its end points does: a corner on F's plane (G's sign
// exact) or the crossing of F's plane with a side of S (G's sign there exact,
// EdgeCone::g_at_f_crossing, without constructing it).
bool SquareDispatcher::half_plane_meets(const EdgeCone& ec, int facet, const SquareGeometry& g) {
  const bool is_f = facet == ec.f().facet();
  if (!is_f && facet != ec.g().facet()) throw InternalError("tet3d: facet " + std::to_string(facet) + " not on the edge");
  const FacetPlane& x = is_f ? ec.f() : ec.g();
  std::array<Sign, 4> sx{};
  for (std::size_t i = 0; i < 4; ++i) sx[i] = x.side(g.corners[i]);
  const Sign bad = ec.convex() ? Sign::Positive : Sign::Negative;  // G's sign off F's part of dP
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t j = (i + 1) % 4;
    if (sx[i] == Sign::Zero && (is_f ? ec.g_on_f(g.corners[i]) : ec.f_on_g(g.corners[i])) != bad) return true;
    if (sx[i] * sx[j] == Sign::Negative) {
      const Sign at = is_f ? ec.g_at_f_crossing(g.corners[i], g.corners[j]) : ec.f_at_g_crossing(g.corners[i], g.corners[j]);
      if (at != bad) return true;
    }
  }
  return false;
}

// F's edges at P vertex v, in vertex_edges(v) order: the first two and how
// many there are. A vertex of F has exactly two on a valid PLC (F's boundary
// passes v once); callers decide what another count means.
SquareDispatcher::FacetEdgesAt SquareDispatcher::facet_edges_at(int vertex, int facet) const {
  FacetEdgesAt at;
  for (const int x : vertex_edges(vertex)) {
    const DomainEdge& de = domain_.edges[static_cast<std::size_t>(x)];
    if (de.facets[0] != facet && de.facets[1] != facet) continue;
    if (at.count < 2) at.edges[static_cast<std::size_t>(at.count)] = x;
    ++at.count;
  }
  return at;
}

// The sector of facet F at P vertex v: the part of F's plane on F's side of
// both lines of F's edges e1, e2 at v (H1 ∩ H2, F's angle at v below 180°),
// of either (H1 ∪ H2, above 180°), or H1 (= H2, exactly 180°); H_i is where
// the sign of e_i's other facet G_i is not `bad` (half_plane_meets). Inside
// the united box B of v (which holds no other P vertex) F's part of
// dP ∩ closure(cone(v)) is this sector ∩ B, while F's triangles may also
// meet B in a piece of another component (the top of the far prong at a slot
// mouth). The section σ = F's plane ∩ S is a segment whose end points are the
// corners of S on F's plane and the crossings of F's plane with sides of S;
// the G_i signs there are exact (orient3d, g_at_f_crossing; for a flat e_i,
// EdgeCone::g_on_f: e_i's side within F's plane, affine along σ too, with
// H_i F's half-plane of e_i's line). σ meets H1 ∪ H2
// iff an end point lies in one of them. For H1 ∩ H2 with no end point in
// both, but each H_i holding one: the G_i signs are affine along σ, so σ
// meets H1 ∩ H2 iff the point x1 where σ crosses line(e1) lies in H2; on
// line(e1), G_2's sign is that of s in x1 = v + s (a1 - v) (G_2(v) = 0, a1
// the other end of e1 strictly in H2 at a convex angle), and x1 lies in S's
// plane x_n = c, so sign(s) = sign(c - v_n) · sign(a1_n - v_n): two exact
// comparisons (a1_n = v_n would put line(e1) parallel to that plane, where
// G_1's sign could not change along σ; c = v_n: x1 = v). In a united box v
// is strictly inside B, so c != v_n there.
bool SquareDispatcher::sector_meets(int vertex, int facet, const SquareGeometry& g) {
  const FacetEdgesAt at = facet_edges_at(vertex, facet);
  if (at.count != 2)
    throw InternalError("tet3d: facet " + std::to_string(facet) + " has " + std::to_string(at.count) +
                        " edges at vertex " + std::to_string(vertex) + " (a vertex box needs two)");
  const std::array<int, 2>& e = at.edges;
  const FacetPlane& fp = plane(facet);
  std::array<const EdgeCone*, 2> ec{&cone(e[0]), &cone(e[1])};
  // G_i's sign at a point x of F's plane (for a flat e_i, its side of e_i's line).
  auto other_sign = [&](std::size_t i, Vec3 x) {
    return ec[i]->f().facet() == facet ? ec[i]->g_on_f(x) : ec[i]->f_on_g(x);
  };
  std::array<Sign, 2> bad{};
  std::array<Vec3, 2> far{};  // the other end of e_i
  const Vec3 pv = domain_.plc.vertices[static_cast<std::size_t>(vertex)];
  for (std::size_t i = 0; i < 2; ++i) {
    bad[i] = ec[i]->convex() ? Sign::Positive : Sign::Negative;
    const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e[i])];
    far[i] = domain_.plc.vertices[static_cast<std::size_t>(de.a == vertex ? de.b : de.a)];
  }
  // F's angle at v: a2 strictly in H1 (convex), on line(e1) (straight), beyond (reflex).
  const Sign a2 = other_sign(0, far[1]);
  const bool straight = a2 == Sign::Zero, reflex = a2 == bad[0];
  // End points of σ with their membership in H1, H2.
  std::array<Sign, 4> sf{};
  for (std::size_t i = 0; i < 4; ++i) sf[i] = fp.side(g.corners[i]);
  std::vector<std::array<bool, 2>> ends;
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t j = (i + 1) % 4;
    std::array<bool, 2> in{};
    if (sf[i] == Sign::Zero) {
      for (std::size_t k = 0; k < 2; ++k) in[k] = other_sign(k, g.corners[i]) != bad[k];
      ends.push_back(in);
    } else if (sf[i] * sf[j] == Sign::Negative) {
      for (std::size_t k = 0; k < 2; ++k) {
        const bool is_f = ec[k]->f().facet() == facet;
        const Sign crossing_side = is_f ? ec[k]->g_at_f_crossing(g.corners[i], g.corners[j])
                                        : ec[k]->f_at_g_crossing(g.corners[i], g.corners[j]);
        in[k] = crossing_side != bad[k];
      }
      ends.push_back(in);
    }
  }
  bool any1 = false, any2 = false, both = false;
  for (const auto& in : ends) {
    any1 = any1 || in[0];
    any2 = any2 || in[1];
    both = both || (in[0] && in[1]);
  }
  if (straight) return any1;
  if (reflex) return any1 || any2;
  if (both) return true;
  if (!any1 || !any2) return false;
  const double vn = axis_coord(pv, g.n), an = axis_coord(far[0], g.n);
  // c = v_n: line(e1) meets S's plane at v only (were it in that plane, σ
  // would lie on it and G_1's sign could not change), so x1 = v, in the sector.
  if (compare(g.c, vn) == Sign::Zero) return true;
  const Sign s = compare(g.c, vn) * compare(an, vn);
  if (s == Sign::Zero) throw InternalError("tet3d: a sector edge of vertex " + std::to_string(vertex) + " parallel to a square");
  return s == Sign::Positive;
}

// F's angle at P vertex v (between its two edges at v) exceeds 180 degrees:
// the far end of F's second edge lies strictly on the side of the first
// edge's other facet G1 that is not P's side of F's part of dP (the test of
// sector_meets, exact orient3d).
bool SquareDispatcher::reflex_at(int vertex, int facet) {
  const FacetEdgesAt at = facet_edges_at(vertex, facet);
  if (at.count != 2) return false;
  const std::array<int, 2>& e = at.edges;
  const EdgeCone& c1 = cone(e[0]);
  const DomainEdge& d2 = domain_.edges[static_cast<std::size_t>(e[1])];
  const Vec3 far2 = domain_.plc.vertices[static_cast<std::size_t>(d2.a == vertex ? d2.b : d2.a)];
  const Sign side = c1.f().facet() == facet ? c1.g_on_f(far2) : c1.f_on_g(far2);
  return side == (c1.convex() ? Sign::Positive : Sign::Negative);
}

// A square S of v's united box B meeting k >= 2 edges of v (thesis §4.4 has
// no such case). S is a face of the finer side (split_square), so a face of
// neighbour leaf cells outside B, and the edge phase (§4.1.4, edge_crowded)
// left no component of P ∩ such a cell with two edges; a connected piece of
// cone(v) ∩ S lies in one such component, so each piece holds at most one
// edge. Directions from v into S form a convex set D (v is off S's plane);
// the part of facet F's sector in D is at most two arcs, each ending at an
// edge of F in D (two arcs only when F's angle at v is reflex and both its
// edges at v meet S). So when every facet of M has an edge in M, the pieces
// of cone(v) ∩ S are bounded inside S only by the two facet rays from the
// crossing x_e of each edge e of M, and the piece at x_e is exactly
// S ∩ wedge(e): the region Case B triangulates for e (cut_square_edge.hpp).
// The neighbour cells triangulate the same pieces, one duplicate per
// component (edge boxes, Case B with the same wedge), so both sides build
// identical triangles. Checked here (exact): every facet of M is a facet of
// an edge of M, and every two edges of M share a facet whose angle at v is
// reflex (a slot or notch between them: the typical case, a notch at a
// prism's cap corner whose two cap edges leave B through one square). Two
// edges sharing a convex-angled facet, or none, would put them in one piece
// or leave the separation unproved: InternalError as before.
bool SquareDispatcher::separate_edge_pieces(int vertex, const Incidence& m) {
  for (const int f : m.facets) {
    bool attached = false;
    for (const int e : m.edges) {
      const DomainEdge& de = domain_.edges[static_cast<std::size_t>(e)];
      attached = attached || de.facets[0] == f || de.facets[1] == f;
    }
    if (!attached) return false;
  }
  for (std::size_t i = 0; i < m.edges.size(); ++i)
    for (std::size_t j = i + 1; j < m.edges.size(); ++j) {
      const DomainEdge& a = domain_.edges[static_cast<std::size_t>(m.edges[i])];
      const DomainEdge& b = domain_.edges[static_cast<std::size_t>(m.edges[j])];
      int shared = -1;
      for (const int f : a.facets)
        if (f >= 0 && (f == b.facets[0] || f == b.facets[1])) shared = f;
      if (shared < 0 || !reflex_at(vertex, shared)) return false;
    }
  return true;
}

Sign SquareDispatcher::local_status(const Incidence& m, Vec3 p) {
  if (!m.vertices.empty() || m.edges.size() > 1 || m.facets.empty() || m.facets.size() > 2)
    throw InternalError("tet3d: no local model for these incidences");
  if (m.facets.size() == 1) return plane(m.facets[0]).side(p);
  const int e = edge_of_facets(m.facets[0], m.facets[1]);
  if (e < 0) throw InternalError("tet3d: no local model for two facets without a common edge");
  return cone(e).status(p);
}

SquareCase SquareDispatcher::triangulate(const FaceSquare& s, const BoxFaces& faces,
                                         std::vector<std::array<int, 3>>& out, Sign inside_hint) {
  const Incidence m = incidences(s, faces);
  if (faces.kind == BoxKind::Vertex) {
    const std::vector<Incidence> pieces = crease_pieces(faces.apex, m);
    if (!pieces.empty()) {
      for (const Incidence& piece : pieces) triangulate_incidence(s, faces, piece, out, inside_hint);
      ++counts_[static_cast<std::size_t>(SquareCase::Pieces)];
      return SquareCase::Pieces;
    }
  }
  return triangulate_incidence(s, faces, m, out, inside_hint);
}

SquareCase SquareDispatcher::triangulate_incidence(const FaceSquare& s, const BoxFaces& faces, const Incidence& m,
                                                   std::vector<std::array<int, 3>>& out, Sign inside_hint) {
  const std::vector<int>& me = m.edges;
  const std::vector<int>& mf = m.facets;

  SquareCase result = SquareCase::Nothing;
  if (faces.kind == BoxKind::Vertex && m.vertices.empty() && me.size() > 1) {
    // Several pieces of cone(v) ∩ S, one per edge (separate_edge_pieces).
    if (!separate_edge_pieces(faces.apex, m)) throw InternalError("tet3d: " + describe(s, faces, m));
    for (const int e : me) triangulate_edge_square(s, corners_, tree_, cone(e), book_, out, warps_);
    ++counts_[static_cast<std::size_t>(SquareCase::BD)];
    return SquareCase::BD;
  }
  if (!m.vertices.empty() || me.size() > 1 || mf.size() > 2) throw InternalError("tet3d: " + describe(s, faces, m));
  if (mf.empty()) {
    if (!me.empty()) throw InternalError("tet3d: " + describe(s, faces, m));
    const GridPoint centre = s.centre();
    const Vec3 C = grid_coordinates(tree_, centre);
    bool inside = true;
    switch (faces.kind) {
      case BoxKind::FromFacet:
      case BoxKind::Empty:
        break;
      case BoxKind::Facet: {
        const Sign side = plane(faces.apex).side(C);
        if (side == Sign::Zero) throw InternalError("tet3d: centre on F, " + describe(s, faces, m));
        inside = side == Sign::Negative;
        break;
      }
      case BoxKind::Edge:
      case BoxKind::TwoFacet: {
        const Sign st = cone(faces.apex).status(C);
        if (st == Sign::Zero) throw InternalError("tet3d: centre on dP, " + describe(s, faces, m));
        inside = st == Sign::Negative;
        break;
      }
      case BoxKind::Vertex: {
        if (inside_hint != Sign::Zero) {
          inside = inside_hint == Sign::Negative;
          ++located_by_neighbours_;
          break;
        }
        const Location loc = locate(domain_, C);
        if (loc == Location::Boundary) throw InternalError("tet3d: centre on dP, " + describe(s, faces, m));
        inside = loc == Location::Inside;
        ++located_;
        break;
      }
    }
    if (inside) {
      const std::vector<GridPoint> ring = square_ring(s, corners_);
      const int c = book_.id(grid_key(centre), [&] { return C; });
      const std::size_t k = ring.size();
      for (std::size_t i = 0; i < k; ++i)
        out.push_back({c, grid_vertex(ring[i], tree_, warps_, book_), grid_vertex(ring[(i + 1) % k], tree_, warps_, book_)});
      result = SquareCase::A;
    }
  } else if (mf.size() == 1) {
    if (!me.empty()) throw InternalError("tet3d: " + describe(s, faces, m));
    triangulate_cut_square(s, corners_, tree_, plane(mf[0]), book_, out, warps_);
    result = SquareCase::C;
  } else {
    const int e = edge_for_square(mf[0], mf[1], square_geometry(s, tree_));
    if (e < 0 || (!me.empty() && me[0] != e))
      throw InternalError("tet3d: two facets without a common edge: " + describe(s, faces, m));
    triangulate_edge_square(s, corners_, tree_, cone(e), book_, out, warps_);
    result = SquareCase::BD;
  }
  ++counts_[static_cast<std::size_t>(result)];
  return result;
}

}  // namespace pqmesh::tet3d
