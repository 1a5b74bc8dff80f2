#pragma once
// Thesis §4.4 Cases B and D on one square S of a box face: the two P facets
// F, G of one P edge E pass through S (with E: Case B; without: Case D).
//
// The edge cone. Near E, P is the wedge bounded by the half-planes of F and G
// from E. With outward facet planes (FacetPlane::side: Negative = P's side),
//   convex edge: P = (P's side of F) ∩ (P's side of G),
//   reflex edge: P = (P's side of F) ∪ (P's side of G).
// Convexity is exact: the third vertex w_G of a facet triangle of G on E lies
// on P's side of F iff the edge is convex (orient3d). Zero means a flat edge
// (coplanar facets that make_domain did not merge because their markers
// differ, plc/merge_coplanar.hpp): one plane split by E's line, treated as a
// convex cone whose "sign of G" at a point of the plane is its side of E's
// line (g_on_f: Negative in F's half-plane), so that every rule below holds
// with F's and G's crossings of a segment at the same point, exactly one of
// them on dP.
// A point p is classified by its two exact signs s_F, s_G: status(p) =
// max(s_F, s_G) for a convex edge, min(s_F, s_G) for a reflex one
// (Negative: inside P, Zero: on dP, Positive: outside). π = S ∩ P.
//
// The ring of S (corners and split points) is extended by the crossings of F
// and G with its segments; a crossing of F is on dP iff it is on P's side of
// G (convex) / beyond G (reflex). Its side of G is decided exactly without
// constructing it: for planes through a common line E = ab,
// F(p)G(q) - F(q)G(p) = λ·orient3d(a, b, p, q) with one sign λ per cone, so
// the sign of G at the crossing of F with segment pq is
// λ·orient3d(a, b, p, q)·s_F(p) (and of F at G's crossing, the negative with
// s_G(p)). orient3d(a, b, p, q) = 0 means E meets the ring: InternalError
// (the first warping pass, §4.3, keeps box edges away from P edges).
//
// Cases (decided exactly; the h/4 tests are constructed distances, as C1/C2):
//   B   E crosses the open (prewarped) square: v = E ∩ S, keyed
//       (EdgeCrossing, S centre, edge), with S's plane coordinate exact and
//       the two others bracketed by exact bisection, so within_ulp_of_segment
//       (v, E) holds; π is star-shaped from v (convex: a wedge at v; reflex: S
//       minus a convex wedge at v), its boundary is one run of the extended
//       ring from the G (or F) exit y to the F (or G) exit x, and v is joined
//       to every segment of that run.
//   E meeting S's closed boundary, or lying in S's plane: InternalError.
//   D   otherwise. With no dP point on the ring: Case A or empty. With dP
//       points on one plane only, π = S ∩ (P's side of that plane) and the
//       square is Case C for that facet (triangulate_cut_square, same keys).
//       With both, a convex edge gives one strip bounded by both chords:
//       D1 (a chord midpoint within h/4 of the centre c; the nearer one,
//       ties to the smaller facet id) fans from that midpoint, D2 fans from
//       c (c inside: all sides; c on a chord: all but it; c beyond chord K:
//       quadrilaterals between π's sides and their projections from c onto
//       K, cut from the smallest key, as C2). A reflex edge gives two
//       disjoint pieces S ∩ (P's side of F) and S ∩ (P's side of G) (the thin
//       exterior wedge separates them), each triangulated as Case C on its
//       own: a gap the thesis leaves (D1 presumes one connected π).
// The result depends only on (S, {F, G}, E, corner set, warps): the order
// in which F, G are passed does not matter, so both boxes sharing S build
// the same triangles (counter-clockwise about +n = S.n).
#include <array>
#include <vector>

#include "pqmesh/domain.hpp"
#include "tet3d/squares/cut_square.hpp"

namespace pqmesh::tet3d {

// The two facets of a P edge and its convexity, decided exactly.
class EdgeCone {
 public:
  // Edge `edge` of domain.edges; its two facets must have facet triangles
  // with the edge's two vertices as a side (make_domain's triangulations do).
  EdgeCone(const Domain3& domain, int edge);
  int edge() const { return edge_; }
  bool convex() const { return convex_; }  // true for a flat edge
  bool flat() const { return flat_; }
  const FacetPlane& f() const { return f_; }  // the smaller facet id
  const FacetPlane& g() const { return g_; }
  Vec3 a() const { return a_; }
  Vec3 b() const { return b_; }
  // Exact status of p (see above): Negative inside P, Zero on dP, Positive outside.
  Sign status(Vec3 p) const;
  // Exact sign of G at the crossing of F with segment pq (s_F(p), s_F(q)
  // strictly opposite), and of F at G's crossing; Zero: E meets pq.
  Sign g_at_f_crossing(Vec3 p, Vec3 q) const;
  Sign f_at_g_crossing(Vec3 p, Vec3 q) const;
  // For x on F's plane: G's sign there (for a flat edge, the side of E's
  // line: Negative in F's half-plane, Positive in G's, Zero on the line);
  // f_on_g the same for x on G's plane.
  Sign g_on_f(Vec3 x) const;
  Sign f_on_g(Vec3 x) const;

 private:
  int edge_ = -1;
  FacetPlane f_, g_;
  Vec3 a_, b_;
  bool convex_ = true;
  bool flat_ = false;
  Sign lambda_ = Sign::Positive;
  Vec3 off_plane_;                // flat: the first P vertex off the plane
  Sign half_f_ = Sign::Positive;  // flat: orient3d(a, b, off_plane_, w_F)
};

enum class EdgeCutCase : std::uint8_t { Empty, Whole, B, OneFacet, D1, D2Inside, D2On, D2Outside, DTwoPieces };

// Appends π's triangles (PointBook ids, right-hand normal along +S.n);
// returns the case taken. `warps` as in triangulate_cut_square.
EdgeCutCase triangulate_edge_square(const FaceSquare& s, const CornerSet& corners, const OctTree& tree,
                                    const EdgeCone& cone, PointBook& book, std::vector<std::array<int, 3>>& out,
                                    const WarpTable* warps = nullptr);

}  // namespace pqmesh::tet3d
