// Local structure of an outward-oriented Plc3 for the alpha computation
// (thesis ch. 3, "Interior angle"). See alpha_star.hpp for the vocabulary.
//
// WHAT IS EXACT AND WHAT IS FLOATING POINT
//   Exact (src/predicates on input coordinates):
//     - the outward vertex triple and the in-plane orientation of each facet
//       (lexicographically lowest vertex of the outer loop in the projection
//       that drops the dominant normal axis is a convex corner, so the sign of
//       its orient2d_projected is the sign of that normal component);
//     - which side of a facet plane an input vertex lies on (orient3d);
//     - the turn of every facet corner, and so which sector a facet spans;
//     - edge shape convex / flat / reflex;
//     - whether an edge ray lies strictly inside the planar sector spanned by
//       two rays (coplanarity by orient3d, betweenness by orient2d_projected);
//     - the local "does the sector leave an edge into P" test when the far
//       ray is an input edge.
//   Exact on rounded constructions (the predicate is exact for the double
//   point it receives, but that point carries rounding error):
//     - the projection of an edge ray into a facet plane (edge-facet
//       candidates) and its sector membership;
//     - the point where the chord of a sector crosses another facet plane,
//       used to decide whether that facet blocks the sector.
//   Floating point: the unit normals and every angle value (atan2 of cross and
//   dot norms via angle_between).

#include "plc/alpha_star.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <tuple>

#include "pqmesh/errors.hpp"

namespace pqmesh::detail {
namespace {

int si(Sign s) { return static_cast<int>(s); }

// Projected coordinates in the cyclic order orient2d_projected uses.
std::pair<double, double> project(Vec3 p, int drop) {
  switch (drop) {
    case 0: return {p.y, p.z};
    case 1: return {p.z, p.x};
    default: return {p.x, p.y};
  }
}

[[noreturn]] void fail(const Plc3& plc, ErrorCode code, const std::string& what, std::vector<std::int64_t> ids,
                       int facet) {
  throw DomainError(code, what, std::move(ids), plc.source.path, plc.source.line_of_element(facet));
}

}  // namespace

AlphaGeometry::AlphaGeometry(const Plc3& plc) : plc_(plc) {
  build_frames();
  build_edges();
  classify_edges();
}

void AlphaGeometry::build_frames() {
  const auto& V = plc_.vertices;
  const int first = plc_.source.first_id;
  frames_.resize(plc_.facets.size());
  for (std::size_t f = 0; f < plc_.facets.size(); ++f) {
    const auto& facet = plc_.facets[f];
    const int fid = int(f);
    if (facet.loops.empty() || facet.loops[0].size() < 3)
      fail(plc_, ErrorCode::DegenerateFacet, "facet " + std::to_string(fid + first) + " has fewer than 3 vertices",
           {fid + first}, fid);
    for (const auto& loop : facet.loops)
      for (int id : loop)
        if (id < 0 || id >= int(V.size()))
          fail(plc_, ErrorCode::DegenerateFacet,
               "facet " + std::to_string(fid + first) + " refers to missing vertex " + std::to_string(id + first),
               {fid + first}, fid);
    const auto& outer = facet.loops[0];
    const std::size_t n = outer.size();
    // Newell normal relative to the first vertex (construction).
    Vec3 normal{};
    const Vec3 o = V[outer[0]];
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const Vec3 c = cross(V[outer[i]] - o, V[outer[i + 1]] - o);
      normal = normal + c;
    }
    FacetFrame& fr = frames_[f];
    fr.drop = dominant_axis(normal);
    // Lexicographically lowest vertex in the projection: a convex corner.
    std::size_t low = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (project(V[outer[i]], fr.drop) < project(V[outer[low]], fr.drop)) low = i;
    const int a = outer[(low + n - 1) % n], v = outer[low], b = outer[(low + 1) % n];
    const Sign turn = orient2d_projected(V[a], V[v], V[b], fr.drop);
    const double nd = axis_coord(normal, fr.drop);
    if (turn == Sign::Zero || nd == 0 || si(turn) != (nd > 0 ? 1 : -1))
      fail(plc_, ErrorCode::DegenerateFacet,
           "facet " + std::to_string(fid + first) + " has no consistent orientation (degenerate or self-crossing loop)",
           {fid + first}, fid);
    fr.drop_sign = turn;
    fr.triple = {a, v, b};
    const double len = norm(normal);
    fr.unit_normal = (1.0 / len) * normal;
  }
}

void AlphaGeometry::build_edges() {
  const int first = plc_.source.first_id;
  struct Entry {
    int a, b, facet, loop, pos;
    bool forward;
  };
  std::vector<Entry> entries;
  corners_.assign(plc_.vertices.size(), {});
  for (std::size_t f = 0; f < plc_.facets.size(); ++f) {
    const auto& loops = plc_.facets[f].loops;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const auto& L = loops[l];
      const std::size_t n = L.size();
      if (n < 3)
        fail(plc_, ErrorCode::DegenerateFacet,
             "facet " + std::to_string(int(f) + first) + " has a loop with fewer than 3 vertices", {int(f) + first},
             int(f));
      for (std::size_t i = 0; i < n; ++i) {
        const int p = L[i], q = L[(i + 1) % n];
        if (p == q)
          fail(plc_, ErrorCode::DegenerateFacet,
               "facet " + std::to_string(int(f) + first) + " repeats vertex " + std::to_string(p + first),
               {int(f) + first}, int(f));
        entries.push_back({std::min(p, q), std::max(p, q), int(f), int(l), int(i), p < q});
        corners_[p].push_back({int(f), L[(i + n - 1) % n], q});
      }
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return std::tie(x.a, x.b, x.facet, x.loop, x.pos) < std::tie(y.a, y.b, y.facet, y.loop, y.pos);
  });
  neighbours_.assign(plc_.vertices.size(), {});
  for (std::size_t i = 0; i < entries.size();) {
    std::size_t j = i;
    while (j < entries.size() && entries[j].a == entries[i].a && entries[j].b == entries[i].b) ++j;
    const Entry& e = entries[i];
    const std::string name = "edge " + std::to_string(e.a + first) + "-" + std::to_string(e.b + first);
    if (j - i == 1)
      fail(plc_, ErrorCode::OpenBoundary, name + " lies on only one facet (" + std::to_string(e.facet + first) + ")",
           {e.a + first, e.b + first}, e.facet);
    if (j - i > 2)
      fail(plc_, ErrorCode::NonManifoldEdge, name + " lies on " + std::to_string(j - i) + " facet sides",
           {e.a + first, e.b + first}, e.facet);
    if (entries[i].forward == entries[i + 1].forward)
      fail(plc_, ErrorCode::NonManifoldEdge,
           name + ": facets " + std::to_string(entries[i].facet + first) + " and " +
               std::to_string(entries[i + 1].facet + first) +
               " traverse it in the same direction (facets not oriented consistently)",
           {e.a + first, e.b + first}, entries[i].facet);
    EdgeInfo info;
    info.a = e.a;
    info.b = e.b;
    for (int k = 0; k < 2; ++k) info.sides[k] = {entries[i + k].facet, entries[i + k].loop, entries[i + k].pos};
    edges_.push_back(info);
    neighbours_[e.a].push_back(e.b);
    neighbours_[e.b].push_back(e.a);
    i = j;
  }
  for (auto& nb : neighbours_) std::sort(nb.begin(), nb.end());
}

int AlphaGeometry::find_edge(int p, int q) const {
  const int a = std::min(p, q), b = std::max(p, q);
  auto it =
      std::lower_bound(edges_.begin(), edges_.end(), std::pair{a, b}, [](const EdgeInfo& e, std::pair<int, int> key) {
        return std::pair{e.a, e.b} < key;
      });
  if (it == edges_.end() || it->a != a || it->b != b) return -1;
  return int(it - edges_.begin());
}

Sign AlphaGeometry::side(int f, Vec3 x) const {
  const auto& t = frames_[f].triple;
  const auto& V = plc_.vertices;
  return orient3d(V[t[0]], V[t[1]], V[t[2]], x);
}

Sign AlphaGeometry::left_in_facet(int f, Vec3 p, Vec3 q, Vec3 r) const {
  return orient2d_projected(p, q, r, frames_[f].drop) * frames_[f].drop_sign;
}

Sign AlphaGeometry::corner_turn(int v, const Corner& c) const {
  const auto& V = plc_.vertices;
  return left_in_facet(c.facet, V[c.prev], V[v], V[c.next]);
}

// The sector runs counter-clockwise (seen from outside) from ray v->b to ray
// v->a; L(x, y) > 0 says y is less than pi counter-clockwise from x.
bool AlphaGeometry::in_closed_sector(int v, const Corner& c, Vec3 x) const {
  const auto& V = plc_.vertices;
  const Vec3 o = V[v], A = V[c.prev], B = V[c.next];
  auto L = [&](Vec3 p, Vec3 q) { return si(left_in_facet(c.facet, o, p, q)); };
  const int turn = L(B, A);
  if (turn > 0) return L(B, x) >= 0 && L(x, A) >= 0;
  if (turn < 0) return !(L(A, x) > 0 && L(x, B) > 0);  // complement of the open convex gap
  return L(B, x) >= 0;
}

bool AlphaGeometry::in_open_sector(int v, const Corner& c, Vec3 x) const {
  const auto& V = plc_.vertices;
  const Vec3 o = V[v], A = V[c.prev], B = V[c.next];
  auto L = [&](Vec3 p, Vec3 q) { return si(left_in_facet(c.facet, o, p, q)); };
  const int turn = L(B, A);
  if (turn > 0) return L(B, x) > 0 && L(x, A) > 0;
  if (turn < 0) return !(L(A, x) >= 0 && L(x, B) >= 0);  // complement of the closed convex gap
  return L(B, x) > 0;
}

std::pair<Vec3, int> AlphaGeometry::halfplane_witness(const EdgeSide& s) const {
  const auto& V = plc_.vertices;
  const auto& L = plc_.facets[s.facet].loops[s.loop];
  const std::size_t n = L.size(), i = std::size_t(s.pos);
  const Vec3 p = V[L[i]], q = V[L[(i + 1) % n]];
  // The facet lies on the left of its directed loop edges.
  for (int cand : {L[(i + 2) % n], L[(i + n - 1) % n]}) {
    const Sign t = left_in_facet(s.facet, p, q, V[cand]);
    if (t != Sign::Zero) return {V[cand], si(t)};
  }
  for (const auto& loop : plc_.facets[s.facet].loops)
    for (int cand : loop) {
      const Sign t = left_in_facet(s.facet, p, q, V[cand]);
      if (t != Sign::Zero) return {V[cand], si(t)};
    }
  const int first = plc_.source.first_id;
  fail(plc_, ErrorCode::DegenerateFacet, "facet " + std::to_string(s.facet + first) + " has all vertices collinear",
       {s.facet + first}, s.facet);
}

void AlphaGeometry::classify_edges() {
  for (auto& e : edges_) {
    const int f0 = e.sides[0].facet, f1 = e.sides[1].facet;
    // Convex iff facet f1's half-plane at e lies on the inner side of f0's plane.
    const auto [w, s] = halfplane_witness(e.sides[1]);
    const int t = s * si(side(f0, w));
    const double between_normals = angle_between(frames_[f0].unit_normal, frames_[f1].unit_normal);
    if (t < 0) {
      e.shape = EdgeShape::Convex;
      e.dihedral = std::numbers::pi - between_normals;
    } else if (t > 0) {
      e.shape = EdgeShape::Reflex;
      e.dihedral = std::numbers::pi + between_normals;
    } else {
      e.shape = EdgeShape::Flat;
      e.dihedral = std::numbers::pi;
    }
  }
}

// Leaving the ray of edge e towards w (w off the line of e), do we enter the
// interior of P? The tangent direction t = w - (w.u)u/|u|^2 is perpendicular
// to e and t.n_i = (w - v).n_i because e lies in both facet planes, so the
// sides of w decide. A convex edge's interior wedge is the intersection of the
// two inner half-spaces, a reflex edge's is their union.
bool AlphaGeometry::interior_from_edge(const EdgeInfo& e, Vec3 w) const {
  const int s0 = si(side(e.sides[0].facet, w)), s1 = si(side(e.sides[1].facet, w));
  switch (e.shape) {
    case EdgeShape::Convex: return s0 < 0 && s1 < 0;
    case EdgeShape::Reflex: return s0 < 0 || s1 < 0;
    case EdgeShape::Flat: return s0 < 0;
  }
  return false;
}

// Visibility of ray v->x (an edge) and ray v->w through the convex planar
// sector S between them (the arc A on the unit sphere). Method:
//  0. S is a convex corner of a facet (w an edge of that corner): S lies in
//     the facet, hence in P (P is closed).
//  1. Another edge ray strictly inside S: report "not visible". When S does lie
//     in P this only hides a pair whose angle is larger than the two pairs
//     through that edge ray, which are themselves candidates and visible, so
//     the minimum is unaffected.
//  2. A facet whose plane has u and w strictly on opposite sides and whose
//     sector contains the crossing direction: S crosses the boundary of P at
//     an interior point (the crossing is transversal), "not visible".
//  3. Otherwise the open arc A misses the link entirely (facets whose plane
//     contains u meet A only at u; a facet plane containing all of A either
//     holds S inside its sector — case 0 — or is left at an edge ray — case
//     1), so A lies wholly inside or wholly outside the cone; the direction
//     in which A leaves the edge ray decides.
bool AlphaGeometry::sees(int v, int x, Vec3 w, int w_vertex, int skip_facet) const {
  const auto& V = plc_.vertices;
  const Vec3 o = V[v], u = V[x];
  // Plane of the sector: the projection that keeps (o, u, w) non-degenerate.
  const Vec3 m = cross(u - o, w - o);
  int axes[3] = {0, 1, 2};
  std::sort(axes, axes + 3, [&](int p, int q) { return std::abs(axis_coord(m, p)) > std::abs(axis_coord(m, q)); });
  int drop = -1;
  Sign o_uw = Sign::Zero;
  for (int k : axes) {
    o_uw = orient2d_projected(o, u, w, k);
    if (o_uw != Sign::Zero) {
      drop = k;
      break;
    }
  }
  if (drop < 0) return false;  // collinear rays: angle 0 or pi, no sector

  if (w_vertex >= 0)
    for (const Corner& c : corners_[v])
      if (((c.prev == x && c.next == w_vertex) || (c.prev == w_vertex && c.next == x)) &&
          corner_turn(v, c) == Sign::Positive)
        return true;

  for (int y : neighbours_[v]) {
    if (y == x || y == w_vertex) continue;
    const Vec3 p = V[y];
    if (orient3d(o, u, w, p) != Sign::Zero) continue;
    if (orient2d_projected(o, u, p, drop) == o_uw && orient2d_projected(o, p, w, drop) == o_uw) return false;
  }

  for (const Corner& c : corners_[v]) {
    if (c.facet == skip_facet) continue;
    const int su = si(side(c.facet, u)), sw = si(side(c.facet, w));
    if (su * sw >= 0) continue;
    // Crossing point of the chord u-w with the facet plane (construction).
    const Vec3 n = frames_[c.facet].unit_normal;
    const double du = dot(u - o, n), dw = dot(w - o, n);
    double t = du != dw ? du / (du - dw) : 0.5;
    t = std::clamp(t, 0.0, 1.0);
    const Vec3 cross_pt = u + t * (w - u);
    if (in_closed_sector(v, c, cross_pt)) return false;
  }

  const int e = find_edge(v, x);
  return e >= 0 && interior_from_edge(edges_[e], w);
}

}  // namespace pqmesh::detail
