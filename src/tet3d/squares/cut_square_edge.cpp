#include "tet3d/squares/cut_square_edge.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "plc/facet_triangle_range.hpp"
#include "pqmesh/errors.hpp"
#include "tet3d/squares/warped_crossing.hpp"

namespace pqmesh::tet3d {

namespace {

Sign smax(Sign a, Sign b) { return static_cast<int>(a) >= static_cast<int>(b) ? a : b; }
Sign smin(Sign a, Sign b) { return static_cast<int>(a) <= static_cast<int>(b) ? a : b; }

const DomainEdge& edge_of(const Domain3& d, int edge) {
  if (edge < 0 || static_cast<std::size_t>(edge) >= d.edges.size())
    throw InternalError("tet3d: no edge " + std::to_string(edge));
  const DomainEdge& e = d.edges[static_cast<std::size_t>(edge)];
  if (e.facets[0] < 0 || e.facets[1] < 0 || e.facets[0] == e.facets[1])
    throw InternalError("tet3d: edge " + std::to_string(edge) + " is not on two facets");
  return e;
}

// The third vertex of a facet triangle of `facet` with side {a, b}: a point
// of the facet's half-plane from the edge, next to the edge.
Vec3 wing(const Domain3& d, int facet, int a, int b) {
  for (const std::size_t t : pqmesh::detail::facet_triangle_range(d, facet)) {
    const auto& tri = d.facet_triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int p = tri[static_cast<std::size_t>(k)], q = tri[static_cast<std::size_t>((k + 1) % 3)];
      if ((p == a && q == b) || (p == b && q == a))
        return d.plc.vertices[static_cast<std::size_t>(tri[static_cast<std::size_t>((k + 2) % 3)])];
    }
  }
  throw InternalError("tet3d: facet " + std::to_string(facet) + " has no triangle on its edge");
}

// A point of the extended ring: a ring point or an on-dP crossing.
struct RPoint {
  Vec3 xyz;
  Sign status = Sign::Positive;
  int tag = -1;       // on dP: 0 = on F's plane, 1 = on G's plane
  int ring = -1;      // index of the ring point, or of the segment's start for a crossing
  bool grid = true;
  int id = -1;        // PointBook id once used
};

}  // namespace

EdgeCone::EdgeCone(const Domain3& domain, int edge)
    : edge_(edge),
      f_(domain, std::min(edge_of(domain, edge).facets[0], edge_of(domain, edge).facets[1])),
      g_(domain, std::max(edge_of(domain, edge).facets[0], edge_of(domain, edge).facets[1])) {
  const DomainEdge& e = edge_of(domain, edge);
  a_ = domain.plc.vertices[static_cast<std::size_t>(e.a)];
  b_ = domain.plc.vertices[static_cast<std::size_t>(e.b)];
  const Vec3 wf = wing(domain, f_.facet(), e.a, e.b), wg = wing(domain, g_.facet(), e.a, e.b);
  // Convex iff G leaves E towards P's side of F (and then F towards G's).
  const Sign fg = f_.side(wg), gf = g_.side(wf);
  if (fg == Sign::Zero && gf == Sign::Zero) {
    // Flat: F and G are one oriented plane (make_domain oriented both
    // outward), split by E's line. P near E is P's side of that plane, the
    // status of a convex cone; the sign "of G" at a point x of the plane is
    // replaced by its side of E's line, Negative in F's half-plane (that of
    // w_F). With c a P vertex off the plane, that side is sign(orient3d(a,
    // b, c, x)) against sign(orient3d(a, b, c, w_F)) = σ; at the crossing x
    // of F with segment pq, orient3d(a, b, c, x) = orient3d(a, b, p, q) ·
    // s_F(p) · s_F(c) in sign, so the crossing formulas below hold with
    // λ = -(s_F(c) · σ).
    flat_ = true;
    for (const Vec3& v : domain.plc.vertices)
      if (f_.side(v) != Sign::Zero) {
        off_plane_ = v;
        break;
      }
    const Sign sc = f_.side(off_plane_);
    half_f_ = orient3d(a_, b_, off_plane_, wf);
    if (sc == Sign::Zero || half_f_ == Sign::Zero)
      throw InternalError("tet3d: flat edge " + std::to_string(edge) + " without a vertex off its plane");
    lambda_ = -(sc * half_f_);
    return;
  }
  if (fg == Sign::Zero || gf == Sign::Zero || fg != gf)
    throw InternalError("tet3d: edge " + std::to_string(edge) + " is flat or its facets are inconsistently oriented");
  convex_ = fg == Sign::Negative;
  // F(p)G(q) - F(q)G(p) = λ·orient3d(a, b, p, q); at p = w_G, q = w_F the
  // left side is F(w_G)·G(w_F).
  const Sign o = orient3d(a_, b_, wg, wf);
  if (o == Sign::Zero) throw InternalError("tet3d: edge " + std::to_string(edge) + " has coplanar facets");
  lambda_ = fg * gf * o;
}

Sign EdgeCone::g_on_f(Vec3 x) const {
  if (!flat_) return g_.side(x);
  return -(orient3d(a_, b_, off_plane_, x) * half_f_);
}

Sign EdgeCone::f_on_g(Vec3 x) const { return flat_ ? -g_on_f(x) : f_.side(x); }

Sign EdgeCone::status(Vec3 p) const {
  const Sign sf = f_.side(p), sg = g_.side(p);
  return convex_ ? smax(sf, sg) : smin(sf, sg);
}

// sign(G(X_F)) = sign(F(p)G(q) - F(q)G(p)) · sign(F(p) - F(q)), the second
// factor being s_F(p) as F changes sign on pq.
Sign EdgeCone::g_at_f_crossing(Vec3 p, Vec3 q) const { return lambda_ * orient3d(a_, b_, p, q) * f_.side(p); }
Sign EdgeCone::f_at_g_crossing(Vec3 p, Vec3 q) const { return -(lambda_ * orient3d(a_, b_, p, q)) * g_.side(p); }

namespace {

// Square S of a box face, its ring and the P edge E, as every step of
// triangulate_edge_square sees them (§4.4 Cases B and D). Contract: built
// from the prewarped square; ring points and the centre resolve through
// `warps` (grid_vertex); `where` names S in error messages.
struct EdgeSquare {
  EdgeSquare(const FaceSquare& s_in, const CornerSet& corners_in, const OctTree& tree_in, const EdgeCone& cone_in,
             PointBook& book_in, const WarpTable* warps_in)
      : s(s_in), corners(corners_in), tree(tree_in), cone(cone_in), book(book_in), warps(warps_in),
        planes{&cone_in.f(), &cone_in.g()}, ring(square_ring(s_in, corners_in)), centre(s_in.centre()),
        C(grid_coordinates(tree_in, centre)) {
    GridPoint hi_corner = s.lo;
    hi_corner.f[s.u] += s.side;
    hi_corner.f[s.v] += s.side;
    lo = grid_coordinates(tree, s.lo);
    hi = grid_coordinates(tree, hi_corner);
    side_len = axis_coord(hi, s.u) - axis_coord(lo, s.u);
    where = "tet3d: edge " + std::to_string(cone.edge()) + ", square at centre (" + std::to_string(centre.f[0]) +
            ", " + std::to_string(centre.f[1]) + ", " + std::to_string(centre.f[2]) + ")";
    ea = cone.a();
    eb = cone.b();
    plane_n = axis_coord(lo, s.n);
    dn = compare(axis_coord(eb, s.n), axis_coord(ea, s.n));
  }

  // Where E crosses S's (prewarped) plane: sign(x - w*) for the crossing's
  // coordinate w* on in-plane axis w, by orient2d of the projection that
  // keeps (n, w): exact.
  Sign rel(double x, int w) const {
    Vec3 p = C;
    axis_ref(p, s.n) = plane_n;
    axis_ref(p, w) = x;
    const int drop = w == s.u ? s.v : s.u;
    const Sign o = orient2d_projected(ea, eb, p, drop);
    // drop v keeps (n, u): o = sign(dn)·sign(x - u*); drop u keeps (v, n): o = -sign(dn)·sign(x - v*).
    return w == s.u ? o * dn : -(o * dn);
  }

  // The mesh vertex of a ring point (a crossing has its id already).
  int id_of(RPoint& p) {
    if (p.id < 0) p.id = grid_vertex(ring[static_cast<std::size_t>(p.ring)], tree, warps, book);
    return p.id;
  }

  int centre_id() { return book.id(grid_key(centre), [&] { return C; }); }

  const FaceSquare& s;
  const CornerSet& corners;
  const OctTree& tree;
  const EdgeCone& cone;
  PointBook& book;
  const WarpTable* warps;
  const FacetPlane* planes[2];
  std::vector<GridPoint> ring;
  GridPoint centre;
  Vec3 C, lo, hi;
  double side_len = 0;
  std::string where;
  Vec3 ea, eb;
  double plane_n = 0;
  Sign dn = Sign::Zero;
};

// Step "Case B test" (§4.4 Case B). Purpose: whether E crosses the open
// prewarped square. Contract: exact (rel); E in S's plane or meeting S's
// closed boundary: InternalError (the first warping pass, §4.3).
bool edge_crosses_open_square(const EdgeSquare& q) {
  if (q.dn == Sign::Zero) {
    if (axis_coord(q.ea, q.s.n) == q.plane_n) throw InternalError(q.where + ": the edge lies in the square's plane");
    return false;
  }
  const Sign u0 = q.rel(axis_coord(q.lo, q.s.u), q.s.u), u1 = q.rel(axis_coord(q.hi, q.s.u), q.s.u);
  const Sign v0 = q.rel(axis_coord(q.lo, q.s.v), q.s.v), v1 = q.rel(axis_coord(q.hi, q.s.v), q.s.v);
  // rel(lo) = sign(lo - u*): u* inside the closed range iff rel(lo) <= 0 <= rel(hi).
  const bool in_u_closed = u0 != Sign::Positive && u1 != Sign::Negative;
  const bool in_v_closed = v0 != Sign::Positive && v1 != Sign::Negative;
  if (!(in_u_closed && in_v_closed)) return false;
  if (u0 == Sign::Zero || u1 == Sign::Zero || v0 == Sign::Zero || v1 == Sign::Zero)
    throw InternalError(q.where + ": the edge meets the square's boundary (first warping pass, §4.3)");
  return true;
}

// The ring points where they are (warped or not) and their exact sides of F
// and G. Contract: a ring point on E: InternalError.
struct RingSides {
  std::vector<Vec3> xyz;
  std::vector<Sign> sf, sg;
};

RingSides ring_sides(const EdgeSquare& q) {
  const std::size_t k = q.ring.size();
  RingSides rs{std::vector<Vec3>(k), std::vector<Sign>(k), std::vector<Sign>(k)};
  for (std::size_t i = 0; i < k; ++i) {
    const Warp* w = q.warps != nullptr ? q.warps->find(q.ring[i]) : nullptr;
    rs.xyz[i] = w != nullptr ? w->at : grid_coordinates(q.tree, q.ring[i]);
    rs.sf[i] = q.cone.f().side(rs.xyz[i]);
    rs.sg[i] = q.cone.g().side(rs.xyz[i]);
    if (rs.sf[i] == Sign::Zero && (q.cone.flat() ? q.cone.g_on_f(rs.xyz[i]) : rs.sg[i]) == Sign::Zero)
      throw InternalError(q.where + ": a ring point lies on the edge");
  }
  return rs;
}

// Step "extend one ring segment" (cut_square_edge.hpp, "The ring of S ... is
// extended"). Purpose: append ring point i and the crossings of F and G with
// segment [i, i + 1] to r, in order along the segment: a crossing on dP as a
// vertex keyed (FacetCrossing, sorted ends, facet), an open interval outside P
// as a marker (no vertex), so that two dP crossings on one segment with P's
// outside between them bound a gap. Contract: E meeting the segment:
// InternalError; a flat edge's two crossings are one point.
void extend_segment(EdgeSquare& q, const RingSides& rs, std::size_t i, std::vector<RPoint>& r) {
  const EdgeCone& cone = q.cone;
  const std::vector<Vec3>& xyz = rs.xyz;
  const std::size_t i1 = (i + 1) % q.ring.size();
  RPoint p;
  p.xyz = xyz[i];
  p.status = cone.convex() ? smax(rs.sf[i], rs.sg[i]) : smin(rs.sf[i], rs.sg[i]);
  // On dP: a point of F's plane is F's (a flat edge: of the facet whose half-plane holds it).
  if (p.status == Sign::Zero)
    p.tag = rs.sf[i] == Sign::Zero && !(cone.flat() && cone.g_on_f(xyz[i]) == Sign::Positive) ? 0 : 1;
  p.ring = static_cast<int>(i);
  r.push_back(p);
  const bool fc = rs.sf[i] * rs.sf[i1] == Sign::Negative, gc = rs.sg[i] * rs.sg[i1] == Sign::Negative;
  Sign g_at_f = Sign::Zero, f_at_g = Sign::Zero;
  if (fc) g_at_f = cone.g_at_f_crossing(xyz[i], xyz[i1]);
  if (gc) f_at_g = cone.f_at_g_crossing(xyz[i], xyz[i1]);
  if ((fc && g_at_f == Sign::Zero) || (gc && f_at_g == Sign::Zero))
    throw InternalError(q.where + ": the edge meets a ring segment (first warping pass, §4.3)");
  // A crossing of one plane is on dP iff the other plane's sign there
  // makes the combined status zero.
  auto on_dp = [&](Sign other) { return cone.convex() ? other == Sign::Negative : other == Sign::Positive; };
  std::array<int, 2> order{0, 1};
  // F's crossing comes first iff G has not changed sign yet there.
  if (fc && gc && g_at_f != rs.sg[i]) order = {1, 0};
  // Signs on the open sub-intervals of the segment (a plane through an end
  // point does not cross it: its sign is the other end's).
  Sign cur_f = rs.sf[i] != Sign::Zero ? rs.sf[i] : rs.sf[i1], cur_g = rs.sg[i] != Sign::Zero ? rs.sg[i] : rs.sg[i1];
  auto mark_if_out = [&] {
    if ((cone.convex() ? smax(cur_f, cur_g) : smin(cur_f, cur_g)) != Sign::Positive) return;
    RPoint gap;
    gap.ring = -1;
    gap.grid = false;
    r.push_back(gap);
  };
  mark_if_out();
  auto push_crossing = [&](int t) {
    RPoint x;
    x.status = Sign::Zero;
    x.tag = t;
    x.ring = static_cast<int>(i);
    x.grid = false;
    const FacetPlane& pl = *q.planes[t];
    const GridPoint& a = std::min(q.ring[i], q.ring[i1]);
    const GridPoint& b = std::max(q.ring[i], q.ring[i1]);
    // End points as this facet's cut sees them (a Fig. 4.7 copy, warp_table.hpp).
    const auto end = [&](std::size_t n) {
      return q.warps != nullptr ? q.warps->at_for_cut(q.ring[n], pl.facet(), xyz[n]) : xyz[n];
    };
    x.id = q.book.id(VertexKey{VertexKind::FacetCrossing, a, b, pl.facet()},
                     [&] { return pl.crossing(end(i), end(i1)); });
    x.xyz = q.book.point(x.id);
    r.push_back(x);
  };
  if (cone.flat()) {
    // F's and G's crossings are one point, on dP as a point of the facet
    // whose half-plane holds it (g_at_f: Negative in F's).
    if (fc) {
      push_crossing(g_at_f == Sign::Negative ? 0 : 1);
      cur_f = cur_g = -cur_f;
      mark_if_out();
    }
    return;
  }
  for (const int t : order) {
    if (t == 0 ? !fc : !gc) continue;
    const bool on = t == 0 ? on_dp(g_at_f) : on_dp(f_at_g);
    (t == 0 ? cur_f : cur_g) = -(t == 0 ? cur_f : cur_g);
    if (!on) {
      mark_if_out();
      continue;
    }
    push_crossing(t);
    mark_if_out();
  }
}

// Step "extended ring": the ring of S with every segment extended
// (extend_segment), in ring order.
std::vector<RPoint> extended_ring(EdgeSquare& q) {
  const RingSides rs = ring_sides(q);
  std::vector<RPoint> r;
  for (std::size_t i = 0; i < q.ring.size(); ++i) extend_segment(q, rs, i, r);
  return r;
}

using Run = std::pair<std::size_t, std::size_t>;

// Step "boundary runs". Purpose: the runs of points not outside P, as
// [start, end] index pairs into r, in ring order from the first run's start.
// Contract: none when every point is outside or none is; each run starts and
// ends on dP, else InternalError.
std::vector<Run> boundary_runs(const EdgeSquare& q, const std::vector<RPoint>& r, std::size_t n_out) {
  const std::size_t m = r.size();
  std::vector<Run> runs;
  if (!(n_out > 0 && n_out < m)) return runs;
  std::size_t i0 = m;
  for (std::size_t i = 0; i < m && i0 == m; ++i)
    if (r[i].status != Sign::Positive && r[(i + m - 1) % m].status == Sign::Positive) i0 = i;
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t i = (i0 + j) % m;
    if (r[i].status == Sign::Positive) continue;
    if (r[(i + m - 1) % m].status == Sign::Positive) runs.push_back({i, i});
    runs.back().second = i;
  }
  for (const auto& [b, e] : runs)
    if (r[b].status != Sign::Zero || r[e].status != Sign::Zero)
      throw InternalError(q.where + ": a run of π's boundary does not start and end on dP");
  return runs;
}

// Step "Case B" (§4.4; cut_square_edge.hpp). Purpose: fan π from v = E ∩ S,
// keyed (EdgeCrossing, S centre, edge): S's plane coordinate exact, the
// in-plane ones bracketed by exact bisection, so within_ulp_of_segment(v, E)
// holds; on a warped square v is E's crossing of the tilted square
// (docs/algorithm/tet3d_warp.md "The Case B vertex on the warped square").
// Contract: one boundary run from one facet to the other, else InternalError.
EdgeCutCase fan_from_edge_crossing(EdgeSquare& q, std::vector<RPoint>& r, const std::vector<Run>& runs,
                                   std::vector<std::array<int, 3>>& out) {
  const std::size_t m = r.size();
  if (runs.size() != 1 || r[runs[0].first].tag == r[runs[0].second].tag)
    throw InternalError(q.where + ": Case B without one boundary run from one facet to the other");
  auto bracket = [&](int w) {
    double a = axis_coord(q.lo, w), b = axis_coord(q.hi, w);  // rel(a) < 0 < rel(b)
    for (int it = 0; it < 2200; ++it) {
      const double mid = a + (b - a) / 2;
      if (mid == a || mid == b) break;
      const Sign sm = q.rel(mid, w);
      if (sm == Sign::Zero) return mid;
      (sm == Sign::Negative ? a : b) = mid;
    }
    return a;
  };
  const int v = q.book.id(VertexKey{VertexKind::EdgeCrossing, q.centre, {}, q.cone.edge()}, [&] {
    Vec3 p = q.C;
    axis_ref(p, q.s.n) = q.plane_n;
    axis_ref(p, q.s.u) = bracket(q.s.u);
    axis_ref(p, q.s.v) = bracket(q.s.v);
    if (!within_ulp_of_segment(p, q.ea, q.eb))
      throw InternalError(q.where + ": edge crossing not within an ulp of the edge");
    if (const auto w = warped_square_crossing(q.ea, q.eb, q.s, q.tree, q.warps)) return *w;
    return p;
  });
  for (std::size_t i = runs[0].first; i != runs[0].second; i = (i + 1) % m) {
    const int p = q.id_of(r[i]);
    out.push_back({v, p, q.id_of(r[(i + 1) % m])});
  }
  return EdgeCutCase::B;
}

// A point of the Case D strip's boundary polygon: its index into the
// extended ring, and the tag of the chord to the next point, or -1 (a ring
// side).
struct PolyPoint {
  std::size_t r;
  int chord_after;
};

// Step "strip polygon" (§4.4 Case D, convex edge). Purpose: π's boundary as
// the two runs joined by the chord of one facet each way. Contract: each
// chord joins two points of one facet, and the two chords belong to
// different facets, else InternalError.
std::vector<PolyPoint> strip_polygon(const EdgeSquare& q, const std::vector<RPoint>& r, const std::vector<Run>& runs) {
  const std::size_t m = r.size();
  if (runs.size() != 2)
    throw InternalError(q.where + ": Case D strip with " + std::to_string(runs.size()) + " boundary runs");
  std::vector<PolyPoint> poly;
  for (std::size_t k = 0; k < 2; ++k) {
    const auto [b, e] = runs[k];
    const std::size_t nb = runs[1 - k].first;
    if (r[e].tag != r[nb].tag) throw InternalError(q.where + ": Case D chord joins two facets");
    for (std::size_t i = b; i != e; i = (i + 1) % m) poly.push_back({i, -1});
    poly.push_back({e, r[e].tag});
  }
  if (r[runs[0].second].tag == r[runs[1].second].tag) throw InternalError(q.where + ": Case D strip with one chord");
  return poly;
}

// Step "D2, centre beyond chord t" (§4.4; as cut_square.cpp's Case C2;
// docs/algorithm/tet3d_warp.md "Chord projections from the warped centre").
// Purpose: quadrilaterals between π's other sides and their projections
// from the centre onto chord t's facet plane, cut from the smallest key.
// Contract: the centre where it is (warped with its corners, keeping its
// sides): a construction only; projections keyed (ChordProjection or
// CrossingProjection, centre, ring point, facet).
void project_onto_chord(EdgeSquare& q, std::vector<RPoint>& r, const std::vector<PolyPoint>& poly, int t,
                        std::vector<std::array<int, 3>>& out) {
  const std::size_t np = poly.size();
  auto pid = [&](std::size_t j) { return q.id_of(r[poly[j % np].r]); };
  const FacetPlane& pl = *q.planes[t];
  const Warp* cw = q.warps != nullptr ? q.warps->find(q.centre) : nullptr;
  const Vec3 from = cw != nullptr ? cw->at : q.C;
  auto projection = [&](std::size_t j) {
    RPoint& p = r[poly[j % np].r];
    if (p.status == Sign::Zero && p.tag == t) return q.id_of(p);
    const VertexKey key = p.grid ? VertexKey{VertexKind::ChordProjection, q.centre,
                                             q.ring[static_cast<std::size_t>(p.ring)], pl.facet()}
                                 : VertexKey{VertexKind::CrossingProjection, q.centre,
                                             q.ring[static_cast<std::size_t>(p.ring)], pl.facet()};
    const Vec3 at = q.book.point(q.id_of(p));
    return q.book.id(key, [&] { return pl.crossing(from, at); });
  };
  for (std::size_t j = 0; j < np; ++j) {
    if (poly[j].chord_after == t) continue;
    const int p = pid(j), qd = pid(j + 1);
    const int pp = projection(j), qq = projection(j + 1);
    if (pp == p) {
      out.push_back({p, qd, qq});
    } else if (qq == qd) {
      out.push_back({p, qd, pp});
    } else {
      append_quad_from_smallest_key(q.book, {p, qd, qq, pp}, out);
    }
  }
}

// Step "convex strip" (§4.4 Case D, D1/D2; cut_square_edge.hpp). Purpose:
// D1 fans from the chord midpoint within h/4 of the centre (the nearer one,
// ties to F), settled on its facet plane, keyed (ChordMidpoint, centre,
// facet); D2 fans from the centre c (inside: all sides; on a chord: all but
// it; beyond chord t: project_onto_chord). Contract: the h/4 test is a
// constructed distance; the centre's sides are exact; c on E or beyond both
// chords: InternalError.
EdgeCutCase triangulate_strip(EdgeSquare& q, std::vector<RPoint>& r, const std::vector<Run>& runs,
                              std::vector<std::array<int, 3>>& out) {
  const std::vector<PolyPoint> poly = strip_polygon(q, r, runs);
  const std::size_t np = poly.size();
  // Chord endpoints per facet tag.
  std::array<std::size_t, 2> chord_at{np, np};
  for (std::size_t j = 0; j < np; ++j)
    if (poly[j].chord_after >= 0) chord_at[static_cast<std::size_t>(poly[j].chord_after)] = j;
  auto pid = [&](std::size_t j) { return q.id_of(r[poly[j % np].r]); };
  auto fan = [&](int apex, int skip_tag) {
    for (std::size_t j = 0; j < np; ++j)
      if (skip_tag < 0 || poly[j].chord_after != skip_tag) out.push_back({apex, pid(j), pid(j + 1)});
  };
  Vec3 mid[2];
  double dist[2];
  for (int t = 0; t < 2; ++t) {
    const std::size_t j = chord_at[static_cast<std::size_t>(t)];
    mid[t] = 0.5 * (q.book.point(pid(j)) + q.book.point(pid(j + 1)));
    dist[t] = in_square_distance(q.s, mid[t], q.C);
  }
  if (std::min(dist[0], dist[1]) <= q.side_len / 4) {
    const int t = dist[0] <= dist[1] ? 0 : 1;
    const FacetPlane& pl = *q.planes[t];
    const int v = q.book.id(VertexKey{VertexKind::ChordMidpoint, q.centre, {}, pl.facet()},
                            [&] { return pl.settle(mid[t], settle_axis(q.s, pl)); });
    fan(v, t);
    return EdgeCutCase::D1;
  }
  const Sign cf = q.cone.f().side(q.C), cg = q.cone.g().side(q.C);
  if (cf == Sign::Negative && cg == Sign::Negative) {
    fan(q.centre_id(), -1);
    return EdgeCutCase::D2Inside;
  }
  if (cf == Sign::Zero || cg == Sign::Zero) {
    if (cf != Sign::Negative && cg != Sign::Negative) throw InternalError(q.where + ": square centre on the edge");
    fan(q.centre_id(), cf == Sign::Zero ? 0 : 1);
    return EdgeCutCase::D2On;
  }
  if (cf == Sign::Positive && cg == Sign::Positive) throw InternalError(q.where + ": square centre beyond both chords");
  project_onto_chord(q, r, poly, cf == Sign::Positive ? 0 : 1, out);
  return EdgeCutCase::D2Outside;
}

}  // namespace

// §4.4 Cases B and D on square S (cut_square_edge.hpp), as a list of steps:
// the Case B test, the extended ring, its boundary runs, then the case.
EdgeCutCase triangulate_edge_square(const FaceSquare& s, const CornerSet& corners, const OctTree& tree,
                                    const EdgeCone& cone, PointBook& book, std::vector<std::array<int, 3>>& out,
                                    const WarpTable* warps) {
  EdgeSquare q(s, corners, tree, cone, book, warps);
  const bool case_b = edge_crosses_open_square(q);
  std::vector<RPoint> r = extended_ring(q);
  const std::size_t m = r.size();
  std::size_t n_out = 0;
  for (const RPoint& p : r) n_out += p.status == Sign::Positive;
  const std::vector<Run> runs = boundary_runs(q, r, n_out);
  if (case_b) return fan_from_edge_crossing(q, r, runs, out);
  if (n_out == m) return EdgeCutCase::Empty;
  if (n_out == 0) {
    // Case A: no dP point on the ring (n_out = 0 leaves no crossing on dP).
    const int c = q.centre_id();
    const std::size_t k = q.ring.size();
    for (std::size_t i = 0; i < k; ++i)
      out.push_back({c, grid_vertex(q.ring[i], tree, warps, book), grid_vertex(q.ring[(i + 1) % k], tree, warps, book)});
    return EdgeCutCase::Whole;
  }
  int on_tag[2] = {0, 0};
  for (const RPoint& p : r)
    if (p.status == Sign::Zero) ++on_tag[p.tag];
  if (on_tag[0] == 0 || on_tag[1] == 0) {
    triangulate_cut_square(s, corners, tree, *q.planes[on_tag[0] == 0 ? 1 : 0], book, out, warps);
    return EdgeCutCase::OneFacet;
  }
  if (!cone.convex()) {
    triangulate_cut_square(s, corners, tree, cone.f(), book, out, warps);
    triangulate_cut_square(s, corners, tree, cone.g(), book, out, warps);
    return EdgeCutCase::DTwoPieces;
  }
  return triangulate_strip(q, r, runs, out);
}

}  // namespace pqmesh::tet3d
