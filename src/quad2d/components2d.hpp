#pragma once
// Connected components of P ∩ C for an axis-aligned square C and a polygon
// with holes P (the 2D analog of thesis §4.1.1 "Duplicate" and §4.1.6 "The
// duplication process"). A quadtree box whose square meets P in several
// components is duplicated, one box per component; crowdedness looks at the
// component of P ∩ ex(b) that contains P ∧ b (containing_component).
//
// Degenerate positions: ONE symbolic perturbation, the outward shift. C is
// replaced by the slightly enlarged rectangle
//     [lo.x - e, hi.x + e] x [lo.y - e^2, hi.y + e^2],   0 < e infinitesimal,
// i.e. the closed square shifted outward, with the x sides moved by e and the
// y sides by the (much smaller) e^2 so that no P edge passes through a
// perturbed corner (the sign of orient2d with a perturbed corner is decided
// by the first non-zero term of its expansion in e; see components2d.cpp).
// Consequences:
//   * a P vertex on ∂C is inside C; a P edge running along a side of C lies
//     inside C; P edges crossing ∂C cross properly, never at a corner;
//   * every crossing of ∂P with ∂C is transversal, so the arcs of ∂C in P
//     alternate with pieces of ∂P inside C;
//   * the components are exactly those of P ∩ C for the CLOSED square: every
//     point of C is interior to the shifted rectangle C_e, so every component
//     of P ∩ C lies in one component of P ∩ C_e; for small e every component
//     of P ∩ C_e contains a point of P ∩ C (P ∩ (C_e \ C) is empty near the
//     parts of ∂C that P does not touch), and distinct components of P ∩ C
//     are at positive distance, so they stay apart. Hence the bijection;
//   * a component may be infinitesimally thin: a single point or a segment in
//     the limit, e.g. a P spike whose tip is a vertex on ∂C coming from
//     outside C, P touching C from outside at a corner of C, or P outside C
//     touching a side along a P edge. It is reported like any other (it is a
//     component of P ∩ C), always contains a P vertex or a P edge piece lying
//     on ∂C, and its boundary arcs have infinitesimal length (constructed
//     t0 == t1);
//   * arcs only record where ∂P CROSSES ∂C. Where P touches ∂C from inside
//     without crossing (a P vertex or edge on ∂C, P inside C near it) there
//     is no arc; that contact is visible in the face lists instead (the
//     vertex or edge lies on ∂C, an exact coordinate test for the caller).
//     So when deciding adjacency of duplicates of neighbouring boxes, compare
//     both the arcs on the common side and the faces on it.
//
// Exactness: inside/outside tests compare input coordinates with square
// coordinates (exact), corner tests use orient2d plus the e-expansion, and
// crossing points on a side are ORDERED exactly by comparing the rational
// crossing coordinates with GMP (ties broken by the derivative with respect to
// the perturbation). The doubles in BoundaryArc are constructions for reports
// only; exact arc ends are identified by the crossing segment ids.
#include <span>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::quad2d {

struct Square {
  Vec2 lo;
  double side = 0;  // > 0
};

// A side of a loop of P: loops[loop][index] -> loops[loop][index + 1].
struct LoopEdge {
  int loop = -1;
  int index = -1;
  friend bool operator==(const LoopEdge&, const LoopEdge&) = default;
};

// An arc of ∂C lying in P, from the exit point of one ∂P piece to the entry
// point of the next, counter-clockwise. Parameters run along ∂C
// counter-clockwise from the lo corner: bottom side [0, s], right [s, 2s],
// top [2s, 3s], left [3s, 4s] (s = side). An arc passing through the lo
// corner has wraps = true (then it is [t0, 4s] + [0, t1]); wraps is decided
// exactly from the crossing order, and it is the only way to tell an almost
// full arc from an infinitesimal one when the constructed t0 and t1 are equal
// (e.g. a hole's vertex poking into C through a side). The whole boundary is
// t0 = 0, t1 = 4s, wraps = false, with both segment ids -1. exit_segment /
// entry_segment are the input segment ids of the ∂P edges at the two ends
// (exact identification of the ends).
struct BoundaryArc {
  double t0 = 0, t1 = 0;
  int exit_segment = -1, entry_segment = -1;
  bool wraps = false;
};

// The P faces incident on one component of P ∩ C (closed, after the outward
// shift). Ids are the Pslg2 vertex ids and input segment ids, sorted.
struct ComponentFaces {
  std::vector<int> vertices;   // P vertices inside C belonging to this component
  std::vector<int> edges;      // input segment ids of P edges meeting this component
  std::vector<BoundaryArc> boundary_arcs;  // arcs of ∂C in this component, by t0
  bool whole_square = false;   // C ⊂ P up to holes lying inside C (no ∂P crosses ∂C)
};

namespace detail {
struct Crossing {
  int side = 0;       // 0 bottom, 1 right, 2 top, 3 left
  bool entry = false; // the directed P edge enters C here
  LoopEdge edge;
  int chain = -1;
  double t = 0;       // construction: parameter along ∂C
};
}  // namespace detail

struct SquareComponents {
  Square square;
  std::vector<ComponentFaces> components;
  // Data for locate_component (internal).
  std::vector<detail::Crossing> crossings;                    // sorted counter-clockwise along ∂C
  std::vector<int> chain_component;                           // chain id -> component
  std::vector<std::pair<LoopEdge, int>> edge_component;       // P edges with a piece inside C
};

// All P edges meeting the closed (shifted) square, as loop edges in loop order.
std::vector<LoopEdge> edges_meeting(const Domain2& domain, const Square& square);
// The same, restricted to a candidate list (e.g. the parent square's list; a
// child square's edges are a subset of its parent's, docs/DESIGN_RULES.md "Data
// layout and speed").
std::vector<LoopEdge> edges_meeting(const Domain2& domain, const Square& square,
                                    std::span<const LoopEdge> candidates);

// Components of P ∩ C. The candidate overload needs every P edge that meets C
// among the candidates (extra candidates are harmless). When no ∂P edge
// crosses ∂C and no P loop lies inside C, whether C lies in P is decided by
// locating the centre of C in `container` (the result for a square holding C,
// e.g. the parent box: O(its edges)); without a container, or when P loops
// lie inside C (the centre might be on one), by scanning all edges of the
// domain (O(n)).
SquareComponents components(const Domain2& domain, const Square& square);
SquareComponents components(const Domain2& domain, const Square& square,
                            std::span<const LoopEdge> candidates,
                            const SquareComponents* container = nullptr);

// The index of the component containing p, or -1 if p lies outside P. p must
// lie in the closed square of `result` and not on ∂P. Decided by shooting
// the ray {p + t (1, 0) + (0, d)}, d infinitesimal (d << e^2), to its first
// hit: a P edge (p is in P iff that edge goes upward, interior on the left)
// or, if none inside C, the right side of C (p is in P iff the next crossing
// counter-clockwise is an entry). Cost O(edges inside C) plus the crossings.
int locate_component(const Domain2& domain, const SquareComponents& result, Vec2 p);

// ex(b) of thesis §4.1.1: the concentric square 5 times larger.
Square extended(const Square& square);

// Which component of P ∩ ex(b) (`outer`, computed for extended(b)) contains
// the component `inner` of P ∩ b, i.e. P ∧ ex(b) for the duplicate box of
// `inner`. Decided exactly by a face: a P vertex of `inner` if it has one
// (it lies in ex(b) and in exactly one outer component), else a P edge of
// `inner` (its piece in b lies in its single piece in ex(b), ex(b) being
// convex), else (inner is the whole square, C in the interior of P) the
// centre of b located by locate_component. -1 if `outer` does not contain
// it (only if outer was not computed for a square containing b).
int containing_component(const Domain2& domain, const SquareComponents& outer, const SquareComponents& inner_result,
                         const ComponentFaces& inner);

}  // namespace pqmesh::quad2d
