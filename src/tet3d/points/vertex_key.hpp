#pragma once
// Identities of mesh vertices on box faces crossed by a P facet (thesis §4.4
// Case C), by defining features (docs/algorithm/tet3d_boxes.md "Vertex
// identities"), so that equal vertices are found by key, never by rounded
// coordinates:
//
//   Grid             a grid point (box corner, split point, square centre): p
//   FacetCrossing    facet F crossing the box-edge segment [p, q] between two
//                    consecutive points of a square ring (p < q)
//   ChordMidpoint    midpoint of the chord F ∩ S of square S (centre p), Case C1
//   ChordProjection  the chord F ∩ S met by the segment from S's centre to the
//                    ring point q (Case C2 with the centre beyond F), S centre p
//   BoxOnFacet       the central vertex of a facet box moved onto F (§4.5.4), box centre p
//   FacetCentre      the central point of F ∩ b (§4.5.4 first case), box centre p
//   Warped           the box vertex (grid point p) moved h/16 away from facet F (§4.3 second pass)
//   BoxClip          segment from the box centre p (beyond F) to the grid point q
//                    clipped at F (§4.5.4 third case, prism tops)
//   EdgeCrossing     P edge E (id in `facet`) crossing the square with centre p
//                    (§4.4 Case B); rounded within an ulp of E, exact on S's plane
//   CrossingProjection  Case D2 with the centre p of S beyond F's chord: the
//                    segment from p to the crossing of the other facet with the
//                    ring segment of S starting (counter-clockwise) at q, clipped at F
//   EdgeMidpoint     the apex on E of the edge box with centre p, edge E (id in
//                    `facet`), §4.5.3: the midpoint of E ∩ I(b), or a point at
//                    1/4 .. 3/4 of it (facet_boxes.hpp); rounded within an ulp of E
//   PVertex          the P vertex with id `facet` (exact input coordinates):
//                    the apex of its united vertex box, §4.5.2
//   TwoFacetApex     the central vertex of the two-facet box with centre p
//                    moved onto facet `facet` (§4.5.5)
//   TwoFacetCentre   the central point of F ∩ b (F = `facet`) of the two-facet
//                    box with centre p (§4.5.5, the facet-box fan)
//   EdgeFacetPoint   a central point of F ∩ b, F = `facet` one of E's two
//                    facets, of the edge box with centre p whose cones from
//                    the apex on E were flat (edge_box_fans.cpp; ours)
//
// Every key names the same point from both boxes sharing the square, so the
// two sides build identical vertices.
#include <cstdint>
#include <functional>

#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {

enum class VertexKind : std::uint8_t {
  Grid,
  FacetCrossing,
  ChordMidpoint,
  ChordProjection,
  BoxOnFacet,
  FacetCentre,
  BoxClip,
  Warped,
  EdgeCrossing,
  CrossingProjection,
  EdgeMidpoint,
  PVertex,
  TwoFacetApex,
  TwoFacetCentre,
  EdgeFacetPoint
};

struct VertexKey {
  VertexKind kind = VertexKind::Grid;
  GridPoint p, q;
  int facet = -1;
  // Field by field (the defaulted form compared the GridPoints with a memcmp
  // call, ~3% of a run inside the point book's probe loop).
  friend bool operator==(const VertexKey& a, const VertexKey& b) {
    return a.kind == b.kind && a.facet == b.facet && a.p.f[0] == b.p.f[0] && a.p.f[1] == b.p.f[1] &&
           a.p.f[2] == b.p.f[2] && a.q.f[0] == b.q.f[0] && a.q.f[1] == b.q.f[1] && a.q.f[2] == b.q.f[2];
  }
  friend auto operator<=>(const VertexKey&, const VertexKey&) = default;
};

inline VertexKey grid_key(const GridPoint& p) { return {VertexKind::Grid, p, {}, -1}; }

// Kinds constructed on their facet's plane (rounded onto it, facet_plane.hpp).
// EdgeCrossing and EdgeMidpoint are not among them: their `facet` field is an
// edge id (the point is within an ulp of the edge, hence near both its facets'
// planes); nor is PVertex (`facet` is a vertex id).
inline bool on_its_facet(const VertexKey& k) {
  return k.kind == VertexKind::FacetCrossing || k.kind == VertexKind::ChordMidpoint ||
         k.kind == VertexKind::ChordProjection || k.kind == VertexKind::BoxOnFacet ||
         k.kind == VertexKind::FacetCentre || k.kind == VertexKind::BoxClip ||
         k.kind == VertexKind::CrossingProjection || k.kind == VertexKind::TwoFacetApex ||
         k.kind == VertexKind::TwoFacetCentre || k.kind == VertexKind::EdgeFacetPoint;
}

struct VertexKeyHash {
  std::size_t operator()(const VertexKey& k) const {
    const GridPointHash h;
    std::size_t x = h(k.p) * 31 + h(k.q);
    x = x * 1000003u + static_cast<std::size_t>(k.facet + 1) * 8u + static_cast<std::size_t>(k.kind);
    return x;
  }
};

}  // namespace pqmesh::tet3d
