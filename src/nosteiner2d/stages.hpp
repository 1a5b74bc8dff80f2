#pragma once
// The stages of the triangulation without boundary Steiner points (thesis
// ch. 5; the entry point is pqmesh/nosteiner.hpp): the upper bound
// g(P) on the min angle any such triangulation can reach, the per-(vertex,
// edge) spirals it is built from, and the Steiner-free CDT baseline.
//
// Definitions (thesis §5.0-§5.1; docs/algorithm/nosteiner2d.md walks them):
//   For a vertex V, an edge E = VU of P and a point W of a closed face of dP
//   disjoint from E ("W interferes with E"), let
//     omega = angle UVW measured from E through the interior of P at V,
//     r     = |VW| / L(E).
//   (E, W) is an eligible pair when |VW| <= L(E), |VW| <= |UW| (Theorem 21's
//   hypotheses) and W lies in the closed interior sector of P at V (so that
//   some triangle of every wedge at V has W in its sector, as the proof of
//   Theorem 21 needs). For it
//     h(E, W) = omega / max(1, -ln r)  ==  min(omega, -1 / ln s_W),
//   where s_W = r^(1/omega) is the shrinking factor of the continuous spiral
//   through W (§5.1, "Continuous spiral").
//   g(P) = min( min over vertices of the interior angle alpha_V,
//               min over eligible (E, W) of h(E, W) ).
//
// The constant, made explicit (proved in docs/algorithm/nosteiner2d.md from
// Theorems 17 and 21): every triangulation of P whose vertices on dP are the
// vertices of P has min angle <= kSteinerFreeBoundConstant * g(P), with
// kSteinerFreeBoundConstant = pi (1 + ln 2) ~= 5.32 (and trivially <= pi/3).
//
// Exactness (docs/DESIGN_RULES.md "Exact decisions"): which faces interfere
// (vertex ids), whether a vertex W is eligible (squared distance comparisons
// and orient2d, exact) and whether an endpoint of an interfering edge lies
// inside each clipping region are exact decisions. Floating point enters only
// in constructions: the parameters where an interfering edge crosses a clipping
// boundary, the angles (atan2) and logarithms, and the minimisation of h along
// an edge piece (golden-section search on a quasiconvex function). Values of g
// are therefore accurate to rounding, not exact; ties between equal values are
// broken by the documented enumeration order (first minimum wins).
#include <string>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/nosteiner.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh {


// The face of dP a witness point W lies on.
struct InterferingFace {
  enum class Kind { Vertex, Edge };
  Kind kind = Kind::Vertex;
  int a = -1, b = -1;  // Vertex: a = vertex id; Edge: the loop side a -> b
};

// The point W of one interfering face minimising h(E, W) (or q, see below).
struct InterferenceWitness {
  InterferingFace face;
  Vec2 point;
  double omega = 0;  // radians, in (0, alpha_V]
  double r = 0;      // |VW| / L(E), in (0, 1]
  double h = 0;      // omega / max(1, -ln r)
};

// Thesis Theorem 23: the empty spiral rho = L(E) s^phi for (V, E) is the
// continuous spiral with the smallest shrinking factor s through an eligible
// interfering point; s = 1 when no eligible point has r < 1.
struct EmptySpiral {
  int vertex = -1;        // V
  int other = -1;         // U, the other end of E
  int far_vertex = -1;    // the other neighbour of V (end of the edge F at V)
  bool ccw = true;        // phi grows counter-clockwise from E (E = V -> next(V))
  double length = 0;      // L(E)
  double alpha = 0;       // interior angle at V (radians): phi ranges over [0, alpha]
  double shrink = 1;      // s in [0, 1] (may underflow to 0: use log_shrink)
  double log_shrink = 0;  // ln s <= 0, exact to rounding even where s underflows
  bool has_eligible = false;
  InterferenceWitness spiral_witness;  // realises s (valid when shrink < 1)
  InterferenceWitness h_witness;       // realises min h over eligible W (valid when has_eligible)
  double min_h = 0;                    // min over eligible W of h(E, W); +inf when none
};

// Thesis §5.1 "Smallest spiral": rho = (L(E)/4) (s^4)^phi.
struct SmallestSpiral {
  double length = 0;      // L(E) / 4
  double shrink = 1;      // s^4 (may underflow to 0)
  double log_shrink = 0;  // 4 ln s
};

// Thesis Theorems 20, 22 and 24: the optimal spiral of a continuous spiral
// (length, shrink) with last spoke at phi = omega: similar triangles with
// angle theta = omega / k at V and spoke ratio a = shrink^theta, where
// k = max(ceil(omega / theta*), ceil(omega / (pi/2))) and theta* = -1/ln(shrink)
// is the relaxed optimum (a = 1/e). min_angle_approx = a * theta (Theorem 17's
// approximation); min_angle is the true smallest angle of one triangle.
struct OptimalSpiral {
  int triangles = 0;  // k
  double theta = 0;
  double a = 1;
  double min_angle_approx = 0;
  double min_angle = 0;
  std::vector<Vec2> spoke_vertices;     // k + 1 points on the continuous spiral, phi = 0 .. omega
  std::vector<double> spoke_log_ratio;  // ln(rho_i / length) = i theta ln s': accurate even where
                                        // rho_i or the points are not representable (see the draft)
};

// Stretch stage (thesis §5.1.1, Figs. 5.8-5.10): the complete wedge at a
// vertex V from its two smallest spirals, S for E = V -> next(V) and T for
// F = V -> prev(V). Polar coordinates are in S's frame (phi from V -> next(V),
// counter-clockwise, in [0, alpha]); radii are kept as logarithms because the
// spirals can shrink below any representable size (see the draft).
struct WedgeSpoke {
  double phi = 0;
  double log_rho = 0;  // ln |V spoke|
  Vec2 point;          // V + rho * direction (a rounded construction)
};

struct VertexWedge {
  enum class Kept { Both, NextOnly, PrevOnly };
  int vertex = -1;
  Kept kept = Kept::Both;
  double phi_x = 0;                             // where S and T meet (Kept::Both)
  bool small_side_fixed = false;                // the fix of §5.1.1 for a one-triangle side was applied
  double phi_x_moved = 0, log_rho_x_moved = 0;  // X after the fix (= X without it), Kept::Both
  // Index of the first of the two spokes of Fig. 5.10 (length |VX|); -1 when
  // there are none (Kept::NextOnly / PrevOnly: one spiral covers the corner)
  // and after polygon_q's spoke floor re-spaced a run of spokes (the indices
  // would not name Fig. 5.10's spokes; docs/algorithm/nosteiner2d.md "Welding
  // and the polygon Q", spoke_floor.hpp).
  int thirds_first = -1;
  std::vector<WedgeSpoke> spokes;               // phi increasing from 0 (on E) to alpha (on F)
  double min_angle = 0;                         // over the triangles (V, spoke_i, spoke_i+1), from polar data
  bool representable = true;                    // every spoke point is distinct from V and the next spoke
};

// next_side / prev_side: the EmptySpiral of (V, V -> next(V)) and (V, V -> prev(V)).
VertexWedge vertex_wedge(const Domain2& domain, const EmptySpiral& next_side, const EmptySpiral& prev_side);

// Stretch stage (thesis §5.1.1 "Welding two spirals for an edge", Fig. 5.11):
// every vertex wedge with its first spokes rotated off the input edges, the
// two triangles per input edge between the wedges of its ends, and the
// remaining polygon Q whose boundary is made of rim edges.
struct PolygonQ {
  TriMesh2 wedges;                         // Q^c: vertices = the input vertices, then the spoke ends
  std::vector<std::vector<int>> loops;     // dQ, one loop per input loop, ids into wedges.vertices,
                                           // interior of Q on the left
  std::vector<VertexWedge> vertex_wedges;  // after the rotations, in loop order
  // Every wedge triangle keeps its orientation after rounding (exact
  // orient2d on the rounded spoke ends). The spoke floor (polygon_q raises
  // every spoke to >= delta_P(V)/16, docs/algorithm/nosteiner2d.md "Welding and
  // the polygon Q") keeps the spokes above double resolution, so this holds on
  // every test input (data/2d, the hard cases, 300 random polygons); when it
  // does not, the pipeline falls back to the CDT of P and says so.
  bool representable = true;
  double min_angle = 0;                    // smallest angle of Q^c (floating point)
};

struct SteinerFreeBound {
  double g = 0;            // radians
  double vertex_term = 0;  // min interior angle
  int vertex_term_vertex = -1;
  double pair_term = 0;              // min over eligible (E, W) of h; +inf when no pair is eligible
  int pair_spiral = -1;              // index into spirals of the realising (V, E)
  std::vector<EmptySpiral> spirals;  // one per (vertex, incident edge): 2 per loop side
  double upper_bound() const;        // min(pi/3, kSteinerFreeBoundConstant * g)
};

struct SteinerFreeOptions {
  // false (the thesis's definition): a side interferes with E only when it is
  // disjoint from E. true: the other side at U (sharing only U with E) also
  // counts, through its eligible part (closer to V than to U). The wedge
  // construction needs it in thin spikes, where the two base corners' spirals
  // otherwise overlap (docs/algorithm/nosteiner2d.md "Welding and the polygon
  // Q"); g(P) is unchanged on the corpus and the 300 random polygons.
  bool sides_at_far_end = false;
};

// Stage 1-2 (thesis Theorems 21, 23): the empty spiral of every (V, E), in
// the order loops, vertices in loop order, E = V -> next(V) then V -> prev(V).
std::vector<EmptySpiral> empty_spirals(const Domain2& domain, const SteinerFreeOptions& options = {});

// Stage 3 (thesis §5.1 "Smallest spiral", Theorem 24).
SmallestSpiral smallest_spiral(const EmptySpiral& empty);

// Stage 4: the optimal spiral of a continuous spiral for the sector [0, omega]
// around V starting along E (Theorem 22). For the smallest optimal spiral pass
// smallest_spiral(e) and omega = e.alpha.
OptimalSpiral optimal_spiral(const Domain2& domain, const EmptySpiral& empty, const SmallestSpiral& spiral,
                             double omega);

// g(P) and its parts.
SteinerFreeBound steiner_free_bound(const Domain2& domain, const SteinerFreeOptions& options = {});

// Stretch stage: Q^c and Q from the spirals of `bound` (computed with
// sides_at_far_end = true for thin spikes, see SteinerFreeOptions).
PolygonQ polygon_q(const Domain2& domain, const SteinerFreeBound& bound);

// Baseline (thesis §2.1, Lawson): the constrained Delaunay triangulation of
// the input vertices and sides, which maximises the min angle over all
// triangulations without any Steiner point.
TriMesh2 steiner_free_cdt(const Domain2& domain);
// Its smallest triangle angle in radians (the polygon's own corners included).
double cdt_min_angle(const Domain2& domain);
// Smallest triangle angle of a triangle mesh, radians (floating point).
double min_triangle_angle(const TriMesh2& mesh);


// ---- Thesis §5.2-§5.3: delta, the shrink of Q to R, and R meshed ----------
// (docs/algorithm/nosteiner2d.md "Delta and the shrink to R", "Meshing R".)

// Thesis §5.1 before Theorem 28: delta(F) for a closed face F (vertex or side)
// of a polygon = min over closed faces F' of F of the distance from F' to the
// closest face disjoint from F'. Deviation: Euclidean distance instead of the
// geodesic distance inside the polygon (a lower bound of it, so R only moves
// less far from dQ; see docs/algorithm/nosteiner2d.md "Delta and the shrink
// to R"). Loops as in PolygonQ (interior on the left); faces of every loop
// count. A measurement, not a decision.
struct PolygonDelta {
  std::vector<std::vector<double>> vertex;  // delta(V) of loop vertex k
  std::vector<std::vector<double>> side;    // delta(E) of loop side k -> k+1 (its two ends included)
};
PolygonDelta polygon_delta(const std::vector<std::vector<Vec2>>& loops);

// The points of dQ, one vector per loop of q.loops.
std::vector<std::vector<Vec2>> q_loop_points(const PolygonQ& q);

// Thesis §5.2 (Fig. 5.14): every side E of Q gets a parallel shrunk side at
// distance delta(E)/4 inside Q. A vertex V of Q with interior angle
// <= 3 pi/4 (an exact decision) gets one R vertex, where the shrunk lines of
// its two sides meet (Case 1); otherwise (Case 2) two R vertices, on the rays
// from V at pi/4 either side of the interior bisector, each on the shrunk line
// of the side on its side, joined by a shrunk side for V.
struct PolygonR {
  std::vector<std::vector<Vec2>> loops;         // one per Q loop, interior on the left
  std::vector<std::vector<int>> vertex_source;  // R vertex -> the Q vertex (index in its Q loop) it comes from
  std::vector<std::vector<int>> side_source;    // R side k -> k+1: Q side index (>= 0), or -1 - (Q vertex index) for Case 2
  std::vector<std::vector<double>> side_delta;  // delta of the source face of each R side (delta(E) or delta(V))
  PolygonDelta delta;                           // of Q
  int case1 = 0, case2 = 0;                     // Q vertices by case
  // false when some shrink distance delta(E)/4 is below kRShrinkResolution
  // times |x| + |y| of its Q vertex: the offsets would be a few thousand ulps
  // or less and rounding decides R's shape (the spiral-depth limit of
  // docs/algorithm/nosteiner2d.md "Known limits" carried into R). R is still
  // constructed.
  bool representable = true;
  bool valid = true;     // every shrunk side keeps its direction and Case 2 sides turn as at V (exact checks)
  std::string failure;   // first violation when !valid
};
inline constexpr double kRShrinkResolution = 1.0 / (1ull << 44);  // 2^-44 ~ 5.7e-14, ~2^8 ulps
PolygonR shrink_q_to_r(const std::vector<std::vector<Vec2>>& q_loops);

// R as a validated Domain2 (make_domain; throws DomainError if R is not a
// polygon with holes, which the tests count as a failure).
Domain2 polygon_r_domain(const PolygonR& r);

// Thesis §5.3 and §5.5.1: R meshed by quad_mesh, with the two properties the
// matching stage (§5.4) needs measured on the result:
//  1. a mesh edge G inside an R side F has L(G) >= c delta(source of F):
//     min_side_edge_over_delta is the smallest L(G) / side_delta(F);
//  2. two mesh edges sharing a vertex have bounded length ratio:
//     max_incident_ratio over all pairs, max_boundary_ratio over the two
//     mesh edges on dR at each boundary vertex.
struct RMesh {
  Domain2 domain;
  QuadMeshResult result;
  double min_side_edge_over_delta = 0;
  double max_incident_ratio = 0;
  double max_boundary_ratio = 0;
  double min_angle = 0;  // radians
};
// Measures the properties on a mesh of R made by quad_mesh (src/nosteiner2d/mesh_r.cpp).
RMesh r_mesh_properties(const PolygonR& r, Domain2 domain, QuadMeshResult result);
// R meshed by quad_mesh with `options`, and its properties.
RMesh mesh_r(const PolygonR& r, const QuadMeshOptions& options = {});

}  // namespace pqmesh
