#include "tet3d/cut_square_edge.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "pqmesh/errors.hpp"
#include "tet3d/warped_crossing.hpp"

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
  for (std::size_t t = 0; t < d.facet_triangles.size(); ++t) {
    if (d.facet_triangle_owner[t] != facet) continue;
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

EdgeCutCase triangulate_edge_square(const FaceSquare& s, const CornerSet& corners, const OctTree& tree,
                                    const EdgeCone& cone, PointBook& book, std::vector<std::array<int, 3>>& out,
                                    const WarpTable* warps) {
  const FacetPlane* planes[2] = {&cone.f(), &cone.g()};
  const std::vector<GridPoint> ring = square_ring(s, corners);
  const std::size_t k = ring.size();
  const GridPoint centre = s.centre();
  const Vec3 C = grid_coordinates(tree, centre);
  GridPoint hi_corner = s.lo;
  hi_corner.f[s.u] += s.side;
  hi_corner.f[s.v] += s.side;
  const Vec3 lo = grid_coordinates(tree, s.lo), hi = grid_coordinates(tree, hi_corner);
  const double side_len = axis_coord(hi, s.u) - axis_coord(lo, s.u);
  const std::string where = "tet3d: edge " + std::to_string(cone.edge()) + ", square at centre (" +
                            std::to_string(centre.f[0]) + ", " + std::to_string(centre.f[1]) + ", " +
                            std::to_string(centre.f[2]) + ")";

  // Where does E cross S's (prewarped) plane? rel(x, w): sign(x - w*) for the
  // crossing's coordinate w* on in-plane axis w, by orient2d of the
  // projection that keeps (n, w): exact.
  const Vec3 ea = cone.a(), eb = cone.b();
  const double plane_n = axis_coord(lo, s.n);
  const Sign dn = compare(axis_coord(eb, s.n), axis_coord(ea, s.n));
  auto rel = [&](double x, int w) {
    Vec3 p = C;
    axis_ref(p, s.n) = plane_n;
    axis_ref(p, w) = x;
    const int drop = w == s.u ? s.v : s.u;
    const Sign o = orient2d_projected(ea, eb, p, drop);
    // drop v keeps (n, u): o = sign(dn)·sign(x - u*); drop u keeps (v, n): o = -sign(dn)·sign(x - v*).
    return w == s.u ? o * dn : -(o * dn);
  };
  bool case_b = false;
  if (dn == Sign::Zero) {
    if (axis_coord(ea, s.n) == plane_n) throw InternalError(where + ": the edge lies in the square's plane");
  } else {
    const Sign u0 = rel(axis_coord(lo, s.u), s.u), u1 = rel(axis_coord(hi, s.u), s.u);
    const Sign v0 = rel(axis_coord(lo, s.v), s.v), v1 = rel(axis_coord(hi, s.v), s.v);
    // rel(lo) = sign(lo - u*): u* inside the closed range iff rel(lo) <= 0 <= rel(hi).
    const bool in_u_closed = u0 != Sign::Positive && u1 != Sign::Negative;
    const bool in_v_closed = v0 != Sign::Positive && v1 != Sign::Negative;
    if (in_u_closed && in_v_closed) {
      if (u0 == Sign::Zero || u1 == Sign::Zero || v0 == Sign::Zero || v1 == Sign::Zero)
        throw InternalError(where + ": the edge meets the square's boundary (first warping pass, §4.3)");
      case_b = true;
    }
  }

  // The extended ring.
  std::vector<Vec3> xyz(k);
  std::vector<Sign> sf(k), sg(k);
  for (std::size_t i = 0; i < k; ++i) {
    const Warp* w = warps != nullptr ? warps->find(ring[i]) : nullptr;
    xyz[i] = w != nullptr ? w->at : grid_coordinates(tree, ring[i]);
    sf[i] = cone.f().side(xyz[i]);
    sg[i] = cone.g().side(xyz[i]);
    if (sf[i] == Sign::Zero && (cone.flat() ? cone.g_on_f(xyz[i]) : sg[i]) == Sign::Zero)
      throw InternalError(where + ": a ring point lies on the edge");
  }
  std::vector<RPoint> r;
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t i1 = (i + 1) % k;
    RPoint p;
    p.xyz = xyz[i];
    p.status = cone.convex() ? smax(sf[i], sg[i]) : smin(sf[i], sg[i]);
    // On dP: a point of F's plane is F's (a flat edge: of the facet whose half-plane holds it).
    if (p.status == Sign::Zero)
      p.tag = sf[i] == Sign::Zero && !(cone.flat() && cone.g_on_f(xyz[i]) == Sign::Positive) ? 0 : 1;
    p.ring = static_cast<int>(i);
    r.push_back(p);
    const bool fc = sf[i] * sf[i1] == Sign::Negative, gc = sg[i] * sg[i1] == Sign::Negative;
    Sign g_at_f = Sign::Zero, f_at_g = Sign::Zero;
    if (fc) g_at_f = cone.g_at_f_crossing(xyz[i], xyz[i1]);
    if (gc) f_at_g = cone.f_at_g_crossing(xyz[i], xyz[i1]);
    if ((fc && g_at_f == Sign::Zero) || (gc && f_at_g == Sign::Zero))
      throw InternalError(where + ": the edge meets a ring segment (first warping pass, §4.3)");
    // A crossing of one plane is on dP iff the other plane's sign there
    // makes the combined status zero.
    auto on_dp = [&](Sign other) { return cone.convex() ? other == Sign::Negative : other == Sign::Positive; };
    std::array<int, 2> order{0, 1};
    // F's crossing comes first iff G has not changed sign yet there.
    if (fc && gc && g_at_f != sg[i]) order = {1, 0};
    // Signs on the open sub-intervals of the segment (a plane through an end
    // point does not cross it: its sign is the other end's); an interval
    // outside P is recorded by a marker (no vertex), so that two dP
    // crossings on one segment with P's outside between them bound a gap.
    Sign cur_f = sf[i] != Sign::Zero ? sf[i] : sf[i1], cur_g = sg[i] != Sign::Zero ? sg[i] : sg[i1];
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
      const FacetPlane& pl = *planes[t];
      const GridPoint& a = std::min(ring[i], ring[i1]);
      const GridPoint& b = std::max(ring[i], ring[i1]);
      // End points as this facet's cut sees them (a Fig. 4.7 copy, warp_table.hpp).
      const auto end = [&](std::size_t n) {
        return warps != nullptr ? warps->at_for_cut(ring[n], pl.facet(), xyz[n]) : xyz[n];
      };
      x.id = book.id(VertexKey{VertexKind::FacetCrossing, a, b, pl.facet()},
                     [&] { return pl.crossing(end(i), end(i1)); });
      x.xyz = book.point(x.id);
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
      continue;
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
  auto id_of = [&](RPoint& p) {
    if (p.id < 0) p.id = grid_vertex(ring[static_cast<std::size_t>(p.ring)], tree, warps, book);
    return p.id;
  };
  const std::size_t m = r.size();
  std::size_t n_out = 0;
  for (const RPoint& p : r) n_out += p.status == Sign::Positive;
  auto centre_id = [&] { return book.id(grid_key(centre), [&] { return C; }); };

  // Runs of points not outside P, as [start, end] index pairs into r.
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  if (n_out > 0 && n_out < m) {
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
        throw InternalError(where + ": a run of π's boundary does not start and end on dP");
  }

  if (case_b) {
    if (runs.size() != 1 || r[runs[0].first].tag == r[runs[0].second].tag)
      throw InternalError(where + ": Case B without one boundary run from one facet to the other");
    // v = E ∩ S: S's plane coordinate exact, the in-plane ones bracketed.
    auto bracket = [&](int w) {
      double a = axis_coord(lo, w), b = axis_coord(hi, w);  // rel(a) < 0 < rel(b)
      for (int it = 0; it < 2200; ++it) {
        const double mid = a + (b - a) / 2;
        if (mid == a || mid == b) break;
        const Sign sm = rel(mid, w);
        if (sm == Sign::Zero) return mid;
        (sm == Sign::Negative ? a : b) = mid;
      }
      return a;
    };
    const int v = book.id(VertexKey{VertexKind::EdgeCrossing, centre, {}, cone.edge()}, [&] {
      Vec3 p = C;
      axis_ref(p, s.n) = plane_n;
      axis_ref(p, s.u) = bracket(s.u);
      axis_ref(p, s.v) = bracket(s.v);
      if (!within_ulp_of_segment(p, ea, eb)) throw InternalError(where + ": edge crossing not within an ulp of the edge");
      // After the first warping pass, E crosses the tilted square
      // (docs/algorithm/tet3d_warp.md "The Case B vertex on the warped square").
      if (const auto w = warped_square_crossing(ea, eb, s, tree, warps)) return *w;
      return p;
    });
    for (std::size_t i = runs[0].first; i != runs[0].second; i = (i + 1) % m) {
      const int p = id_of(r[i]);
      out.push_back({v, p, id_of(r[(i + 1) % m])});
    }
    return EdgeCutCase::B;
  }

  if (n_out == m) return EdgeCutCase::Empty;
  if (n_out == 0) {
    // Case A: no dP point on the ring (n_out = 0 leaves no crossing on dP).
    const int c = centre_id();
    for (std::size_t i = 0; i < k; ++i)
      out.push_back({c, grid_vertex(ring[i], tree, warps, book), grid_vertex(ring[(i + 1) % k], tree, warps, book)});
    return EdgeCutCase::Whole;
  }
  int on_tag[2] = {0, 0};
  for (const RPoint& p : r)
    if (p.status == Sign::Zero) ++on_tag[p.tag];
  if (on_tag[0] == 0 || on_tag[1] == 0) {
    triangulate_cut_square(s, corners, tree, *planes[on_tag[0] == 0 ? 1 : 0], book, out, warps);
    return EdgeCutCase::OneFacet;
  }
  if (!cone.convex()) {
    triangulate_cut_square(s, corners, tree, cone.f(), book, out, warps);
    triangulate_cut_square(s, corners, tree, cone.g(), book, out, warps);
    return EdgeCutCase::DTwoPieces;
  }
  // Convex strip: two runs, joined by the chord of one facet each way.
  if (runs.size() != 2)
    throw InternalError(where + ": Case D strip with " + std::to_string(runs.size()) + " boundary runs");
  struct PolyPoint {
    std::size_t r;
    int chord_after;  // tag of the chord to the next point, or -1 (a ring side)
  };
  std::vector<PolyPoint> poly;
  for (std::size_t q = 0; q < 2; ++q) {
    const auto [b, e] = runs[q];
    const std::size_t nb = runs[1 - q].first;
    if (r[e].tag != r[nb].tag) throw InternalError(where + ": Case D chord joins two facets");
    for (std::size_t i = b; i != e; i = (i + 1) % m) poly.push_back({i, -1});
    poly.push_back({e, r[e].tag});
  }
  if (r[runs[0].second].tag == r[runs[1].second].tag) throw InternalError(where + ": Case D strip with one chord");
  const std::size_t np = poly.size();
  // Chord endpoints per facet tag.
  std::array<std::size_t, 2> chord_at{np, np};
  for (std::size_t j = 0; j < np; ++j)
    if (poly[j].chord_after >= 0) chord_at[static_cast<std::size_t>(poly[j].chord_after)] = j;
  auto pid = [&](std::size_t j) { return id_of(r[poly[j % np].r]); };
  auto fan = [&](int apex, int skip_tag) {
    for (std::size_t j = 0; j < np; ++j)
      if (skip_tag < 0 || poly[j].chord_after != skip_tag) out.push_back({apex, pid(j), pid(j + 1)});
  };
  Vec3 mid[2];
  double dist[2];
  for (int t = 0; t < 2; ++t) {
    const std::size_t j = chord_at[static_cast<std::size_t>(t)];
    mid[t] = 0.5 * (book.point(pid(j)) + book.point(pid(j + 1)));
    dist[t] = in_square_distance(s, mid[t], C);
  }
  if (std::min(dist[0], dist[1]) <= side_len / 4) {
    const int t = dist[0] <= dist[1] ? 0 : 1;
    const FacetPlane& pl = *planes[t];
    const int v = book.id(VertexKey{VertexKind::ChordMidpoint, centre, {}, pl.facet()},
                          [&] { return pl.settle(mid[t], settle_axis(s, pl)); });
    fan(v, t);
    return EdgeCutCase::D1;
  }
  const Sign cf = cone.f().side(C), cg = cone.g().side(C);
  if (cf == Sign::Negative && cg == Sign::Negative) {
    fan(centre_id(), -1);
    return EdgeCutCase::D2Inside;
  }
  if (cf == Sign::Zero || cg == Sign::Zero) {
    if (cf != Sign::Negative && cg != Sign::Negative) throw InternalError(where + ": square centre on the edge");
    fan(centre_id(), cf == Sign::Zero ? 0 : 1);
    return EdgeCutCase::D2On;
  }
  if (cf == Sign::Positive && cg == Sign::Positive) throw InternalError(where + ": square centre beyond both chords");
  // Centre beyond chord t: project π's other sides onto it from the centre.
  const int t = cf == Sign::Positive ? 0 : 1;
  const FacetPlane& pl = *planes[t];
  // From the centre where it is (warped with its corners, keeping its sides;
  // as cut_square.cpp's Case C2): a construction only.
  const Warp* cw = warps != nullptr ? warps->find(centre) : nullptr;
  const Vec3 from = cw != nullptr ? cw->at : C;
  auto projection = [&](std::size_t j) {
    RPoint& p = r[poly[j % np].r];
    if (p.status == Sign::Zero && p.tag == t) return id_of(p);
    const VertexKey key = p.grid ? VertexKey{VertexKind::ChordProjection, centre, ring[static_cast<std::size_t>(p.ring)],
                                             pl.facet()}
                                 : VertexKey{VertexKind::CrossingProjection, centre,
                                             ring[static_cast<std::size_t>(p.ring)], pl.facet()};
    const Vec3 at = book.point(id_of(p));
    return book.id(key, [&] { return pl.crossing(from, at); });
  };
  for (std::size_t j = 0; j < np; ++j) {
    if (poly[j].chord_after == t) continue;
    const int p = pid(j), q = pid(j + 1);
    const int pp = projection(j), qq = projection(j + 1);
    if (pp == p) {
      out.push_back({p, q, qq});
    } else if (qq == q) {
      out.push_back({p, q, pp});
    } else {
      append_quad_from_smallest_key(book, {p, q, qq, pp}, out);
    }
  }
  return EdgeCutCase::D2Outside;
}

}  // namespace pqmesh::tet3d
