// alpha for a 3D domain: the smallest interior angle between two faces
// (thesis ch. 3, "Interior angle"), with the faces that realise it.
//
// WHICH CANDIDATES ARE EVALUATED, AND WHY THAT SUFFICES
// The thesis remarks that alpha is always realised by two edges or by an edge
// and a facet. At every vertex v we evaluate
//   (b1) every facet corner: the facet's own interior angle between its two
//        edges at v (exact turn, may exceed pi) -- "edge-edge";
//   (b2) every other pair of edges at v: their convex angle, when the convex
//        planar sector between them lies in P (AlphaGeometry::sees) --
//        "edge-edge";
//   (c)  every edge e at v and facet g at v not containing e: the angle
//        between e and its orthogonal projection p into g's plane, when p lies
//        strictly inside g's sector at v and sees e -- "edge-facet".
// and at every edge
//   (a)  the interior dihedral angle -- "facet-facet (dihedral)".
// Why (c) needs only the projection: for rays r in g's plane the cosine of the
// angle between e and r is |p| cos(angle(r, p)), unimodal in r, so over g's
// sector the minimum is at p (if inside) or at a bounding ray of the sector,
// which is an edge of g at v and so already a candidate of (b). When
// visibility cuts the sector, the first ray where it switches is one whose
// sector from e touches an edge ray x of P (arcs through a fixed point first
// touch a spherical polygon at a vertex), and the visible pair (e, x) has a
// smaller angle. Facet-facet at a shared vertex (d) is never evaluated: for a
// fixed ray in one facet the best partner is found as in (c), and along the
// first facet's sector the angle to the other plane is largest in the middle,
// so the minimum is at a bounding edge, i.e. an edge-facet pair.
// Every pair whose angle could not be smaller than the current minimum skips
// the visibility test, so pairs with a wrongly overestimated angle never
// change the result; the dihedral minimum is kept as a sanity check
// (thesis: alpha <= min dihedral) and reported only if it is strictly smaller.
#include <cmath>
#include <limits>
#include <numbers>

#include "plc/alpha_star.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh {
namespace {

struct Best {
  AlphaResult r;
  Best() { r.radians = std::numeric_limits<double>::infinity(); }
  // Ties keep the earlier candidate, so the order of evaluation (vertex id,
  // then corners, edge pairs, edge-facet pairs; dihedrals last) fixes the
  // reported pair deterministically.
  void offer(double angle, int apex, FaceRef first, FaceRef second, const char* kind) {
    if (!(angle < r.radians)) return;
    r.radians = angle;
    r.apex = apex;
    r.first = first;
    r.second = second;
    r.kind = kind;
  }
};

// Interior angle of a facet corner, measured inside the facet.
double corner_angle(const detail::AlphaGeometry& G, int v, const detail::Corner& c) {
  const auto& V = G.plc().vertices;
  const double phi = angle_between(V[c.next] - V[v], V[c.prev] - V[v]);
  switch (G.corner_turn(v, c)) {
    case Sign::Positive: return phi;
    case Sign::Negative: return 2 * std::numbers::pi - phi;
    case Sign::Zero: break;
  }
  if (dot_sign(V[v], V[c.prev], V[c.next]) == Sign::Positive) {
    const int first = G.plc().source.first_id;
    throw DomainError(ErrorCode::DegenerateFacet,
                      "facet " + std::to_string(c.facet + first) + " folds back on itself at vertex " +
                          std::to_string(v + first),
                      {c.facet + first, v + first}, G.plc().source.path, G.plc().source.line_of_element(c.facet));
  }
  return std::numbers::pi;
}

}  // namespace

AlphaResult compute_alpha(const Plc3& oriented) {
  if (oriented.facets.empty()) throw DomainError(ErrorCode::EmptyDomain, "the domain has no facets");
  const detail::AlphaGeometry G(oriented);
  const auto& V = oriented.vertices;
  Best best;

  for (int v = 0; v < G.vertex_count(); ++v) {
    const auto& corners = G.corners(v);
    const auto& nbrs = G.neighbours(v);
    for (const auto& c : corners)
      best.offer(corner_angle(G, v, c), v, FaceRef::edge(v, c.next), FaceRef::edge(v, c.prev), "edge-edge");

    for (std::size_t i = 0; i < nbrs.size(); ++i)
      for (std::size_t j = i + 1; j < nbrs.size(); ++j) {
        const int x = nbrs[i], y = nbrs[j];
        const double phi = angle_between(V[x] - V[v], V[y] - V[v]);
        if (phi < best.r.radians && G.sees(v, x, V[y], y, -1))
          best.offer(phi, v, FaceRef::edge(v, x), FaceRef::edge(v, y), "edge-edge");
      }

    for (int x : nbrs) {
      const auto& e = G.edges()[std::size_t(G.find_edge(v, x))];
      const Vec3 u = V[x] - V[v];
      for (const auto& c : corners) {
        const int g = c.facet;
        if (g == e.sides[0].facet || g == e.sides[1].facet) continue;  // e is a subface of g
        const Vec3 n = G.frames()[std::size_t(g)].unit_normal;
        const Vec3 p = u - dot(u, n) * n;
        if (p == Vec3{}) continue;  // e perpendicular to g: every ray of g is at pi/2
        const double phi = angle_between(u, p);
        if (!(phi < best.r.radians)) continue;
        const Vec3 target = V[v] + p;
        if (G.in_open_sector(v, c, target) && G.sees(v, x, target, -1, g))
          best.offer(phi, v, FaceRef::edge(v, x), FaceRef::facet(g), "edge-facet");
      }
    }
  }

  double min_dihedral = std::numeric_limits<double>::infinity();
  int min_edge = -1;
  for (std::size_t i = 0; i < G.edges().size(); ++i)
    if (G.edges()[i].dihedral < min_dihedral) {
      min_dihedral = G.edges()[i].dihedral;
      min_edge = int(i);
    }
  if (min_edge >= 0) {
    const auto& e = G.edges()[std::size_t(min_edge)];
    const int f0 = std::min(e.sides[0].facet, e.sides[1].facet), f1 = std::max(e.sides[0].facet, e.sides[1].facet);
    best.offer(min_dihedral, e.a, FaceRef::facet(f0), FaceRef::facet(f1), "facet-facet (dihedral)");
  }
  best.r.min_dihedral_radians = min_dihedral;
  return best.r;
}

}  // namespace pqmesh
