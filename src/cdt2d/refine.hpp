#pragma once
// Delaunay refinement of a constrained Delaunay triangulation (Ruppert's
// algorithm with Chew's constrained setting and Ungor's off-centers; the
// small-angle rules follow Shewchuk, "Delaunay refinement algorithms for
// triangular mesh generation", CGTA 22, 2002). An optional quality pass for
// the point sets of the 2D meshers (thesis §2.1 recalls the CDT).
//
// Input: as constrained_delaunay(in, keep_inside = true): closed constraint
// loops, the domain on their left. The CDT is built first, then:
//   - subsegments: the constrained edges; each belongs to one input
//     constraint (its "origin", the smallest index among constraints that
//     cover it when a side is given twice). A subsegment is encroached by a
//     vertex in its closed diametral circle (exact dot_sign: the angle the
//     vertex sees the subsegment under is >= 90 degrees). Encroached
//     subsegments are split first (a queue, FIFO).
//   - bad triangles: inside triangles with smallest angle < min_angle_degrees
//     (a floating-point measurement; it only chooses what to improve, never
//     validity). A priority queue, smallest angle first (ties: the first
//     queued; seeded in slot order), re-validated on pop. Worst first keeps
//     the count low at high targets: at 33 degrees on the 2D benchmark's
//     shapes it made 1.3 to 4 times fewer points than first-in first-out.
//     For a bad triangle the off-center (Ungor: the circumcenter, pulled
//     towards the shortest edge so that the new triangle on that edge just
//     meets the target) is located by a straight walk from the triangle that
//     never crosses a constrained edge. If the walk meets a constrained edge
//     (the point is beyond it or on it: outside the domain or across a
//     constraint) that subsegment is split instead. Otherwise, if the point
//     encroaches a constrained edge of its Bowyer-Watson cavity (the edges the
//     new vertex would see), those subsegments are split instead (Ruppert);
//     else the point is inserted (1-3 / 2-4 split + Lawson flips that never
//     cross a constraint).
//   - splitting a subsegment ab: at its midpoint, or, when exactly one end is
//     a sharp input vertex (two constraints meet there at < 60 degrees inside
//     the domain), at the power-of-two distance from that vertex that lies in
//     [|ab|/3, 2|ab|/3] (concentric shells, Ruppert/Shewchuk). The point is
//     then rounded onto the ORIGINAL input segment AB by round_onto_segment
//     (a slanted segment's midpoint has no exact double); among the rounding
//     and its neighbours up to 3 ulps away the first one is taken that stays
//     on AB and, preferably, not strictly right of the (bent) subsegment
//     a -> b. The split is refused (and never retried) when |ab| < |AB| / 2^12,
//     when no such rounding exists, or when the exact validity conditions of
//     Triangulation::split_constrained_edge fail (refine_ops.cpp: new inside
//     triangles strictly counter-clockwise; a point right of a -> b only into
//     a "trusted" outside triangle, so the domain never grows over anything).
//     A bad triangle whose new point encroaches only refused subsegments is
//     given up (it stays in the mesh; target_reached is then false).
//   - excused triangles (never refined, Shewchuk §5 "small input angles"):
//     the smallest angle is at a sharp input vertex and both its edges there
//     are constrained (the triangle fills the input corner), or the shortest
//     edge joins points on two input segments that meet at a sharp vertex.
//     Near such corners the result can stay below the input angle (measured:
//     down to about 0.8 x min(alpha, target)).
// Without constraint splits (RefineOptions::split_constraints = false, the
// setting of Triangle's -Y; used by the triangulation without boundary
// Steiner points, src/nosteiner2d/refined_candidate.hpp; refine_inside.cpp):
// no subsegment is queued or split, encroachment as such is ignored. For a
// bad triangle t with new point c (off-center or circumcenter), c is
// inserted when
//   (a) the walk from t reaches c strictly inside an inside triangle or on an
//       unconstrained edge: c is strictly inside the domain;
//   (b) no vertex of c's cavity (the vertices c is joined to) is closer to c
//       than t's shortest edge;
//   (c) no constrained edge ab of the cavity is flat for c: c encroaches ab
//       (exact dot_sign) and the triangle abc has an angle below the target
//       at a or b - a bad triangle whose circumcenter is on or beyond ab,
//       which could never be improved.
// When (a) fails at a constrained edge or (c) fails at an edge ab, the
// apexes of ab (on its bisector, base angles 60, 45, 32 degrees) are tried,
// then the point halfway from the midpoint of t's shortest edge to c; the
// first that passes (a), (b) and (c) is inserted and t re-queued (for an
// apex, (b) uses the smaller of t's shortest edge and 0.99^(1/2) |a apex|, and (c)
// skips ab). Otherwise t is given up (it stays; target_reached is then false
// unless it is excused). Distances and angles in (b), (c) are doubles: a
// choice between inserting and giving up, never a validity decision.
// Edges: every edge an insertion makes joins the new point to a cavity
// vertex, so it is at least as long as t's shortest edge (a mesh edge) or,
// for an apex, 0.99^(1/2) |a apex| >= 0.58 |ab| (ab a constraint: an edge of
// the first mesh). Hence no edge is ever shorter than 0.58 times the
// shortest edge of the constrained Delaunay triangulation: points do not
// accumulate (termination itself is by max_new_points; the fallback points
// are fixed points of their edge or triangle, each inserted at most once, a
// second walk ending on the vertex). Away from constraints (b) never
// fires for targets <= 30 degrees: the circumcenter is at distance R = l / (2
// sin a) > l from every cavity vertex (a < 30 the smallest angle, l the
// shortest edge), Ungor's off-center at least (l / 2) sqrt(1 + (0.95 cot(theta
// / 2))^2) > l.
// Termination: every insertion counts against max_new_points (0 means twice
// the number of input points, which is too few for a coarse polygon: pass a
// cap for those), so the pass always ends. Besides the cap, subsegments are
// never split below |AB| / 2^12, and a refused split is never retried, so a
// bad triangle is re-queued only after an insertion; measured on the random
// polygons (1-degree spikes included) the pass ends without the cap.
//
// Files: refine.cpp (main loop, walk, cavity, splits), refine_setup.cpp
// (subsegment origins, sharp vertices, output chains), refiner.hpp (state),
// refine_ops.cpp (the Triangulation operations: insertion and constrained
// edge split keeping the inside labels).
// Exactness: every decision (walk, cavity incircle, encroachment, split
// validity) is an exact predicate; constructions (off-centers, split points)
// are doubles. Deterministic: queues seeded in slot order, ties by queue order.
//
// Vertices on segments: an input point whose constraints all belong to one
// segment lies on that segment (a Steiner point of the caller); the excuse
// rule for two segments meeting at a sharp vertex applies to it too.
//
// Output vertices: input points first (same ids), then inserted points in
// insertion order. Steiner points on a constraint satisfy
// within_ulp_of_segment(p, A, B) for its input constraint A -> B (the rule
// check_mesh applies). Errors: as constrained_delaunay (InternalError).
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "cdt2d/constrained_delaunay.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::cdt2d {

struct RefineOptions {
  double min_angle_degrees = 20;   // target (Ruppert's guarantee needs <= 20.7 with input angles >= 60)
  std::size_t max_new_points = 0;  // cap on inserted points; 0 = 2 * number of input points
  bool off_centers = true;         // false: plain circumcenters
  // false: no point is ever put on a constrained edge (Triangle's -Y; the
  // subsegments stay the input constraints). Encroachment is then ignored: a
  // bad triangle's new point is inserted when the walk reaches it strictly
  // inside the domain (not on or beyond a constrained edge) and it is at
  // least as far from every vertex of its cavity as the triangle's shortest
  // edge is long; otherwise the triangle is given up (see "Without
  // constraint splits" above).
  bool split_constraints = true;
};

struct RefineResult {
  std::vector<Vec2> points;                     // input points first (same ids), then the new ones
  std::vector<std::array<int, 3>> triangles;    // CCW, inside only (as constrained_delaunay with keep_inside)
  std::vector<std::array<int, 2>> constraints;  // constraint pieces after splitting, directed as given (interior on the left)
  std::vector<int> constraint_origin;           // per output piece: index of the input constraint it comes from
  std::size_t inserted = 0;                     // new points (interior + on constraints)
  std::size_t inserted_on_constraints = 0;      // of which on constraints
  std::size_t refused_splits = 0;               // subsegment splits refused (too short, rounding, orientation)
  std::size_t excused = 0;                      // bad triangles excused at the end (small input angles)
  // split_constraints off ("Without constraint splits"): bad triangles given
  // up by rule (a), (b), (c), and apex points inserted.
  std::size_t given_up_outside = 0, given_up_near = 0, given_up_flat = 0, apex_points = 0, halfway_points = 0;
  bool cap_reached = false;                     // stopped by max_new_points
  bool target_reached = false;                  // every inside triangle not excused meets the target
};

// Optional: the input segments the constraints lie on. The quadtree mesher
// passes every loop side as a chain of short constraints between points that
// are themselves rounded onto the side; then a Steiner point must be rounded
// onto the SIDE (the segment check_mesh knows), not onto the short piece, and
// the small-angle rules must see which pieces belong to one side.
//   constraint_segment[c]: segment id of constraint c (>= 0), one per constraint;
//   segment_ends[s]: the endpoints of segment s (the constraint's ends must
//   lie on it: exactly, or within an ulp as within_ulp_of_segment says).
// Empty (the default): every constraint is its own segment. With segments,
// the minimum piece length is |segment| / 2^12 and a sharp pair is a pair of
// segments.
struct SegmentSupport {
  std::vector<int> constraint_segment;
  std::vector<std::array<Vec2, 2>> segment_ends;
};

RefineResult refine_constrained_delaunay(const CdtInput& in, const RefineOptions& options = {},
                                         const SegmentSupport& support = {});
// The same, taking the input's points instead of copying them (in.points is
// left empty; the result's points start with them). Give in.points a capacity
// of n + new_point_allowance(n, options) to spare it a reallocation.
RefineResult refine_constrained_delaunay(CdtInput&& in, const RefineOptions& options = {},
                                         const SegmentSupport& support = {});

// An allowance for the points refinement adds, not a limit: the point,
// triangle and vertex arrays are reserved for this many more than the n input
// points, so the usual handful of new points never reallocates (copies) them.
// Reserve that is never touched costs address space only.
std::size_t new_point_allowance(std::size_t n, const RefineOptions& options);

// Rounds p (a point constructed near the segment ab) onto it: moves p by
// single ulps towards the line ab along the axis where the line's normal has
// the larger component until within_ulp_of_segment(p, a, b) holds
// (predicates.hpp). nullopt when 64 steps do not suffice (p was not near ab).
std::optional<Vec2> round_onto_segment(Vec2 p, Vec2 a, Vec2 b);

}  // namespace pqmesh::cdt2d
