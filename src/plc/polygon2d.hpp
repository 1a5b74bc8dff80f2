#pragma once
// Exact 2D primitives on segments and polygon loops (docs/DESIGN_RULES.md
// "Exact decisions"): every decision is an orient2d / coordinate comparison on
// the input doubles. Used for the 2D domain and for facets worked in their
// exact axis projection.
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "predicates/predicates.hpp"

namespace pqmesh::detail {

// p lies on the closed segment ab (a != b).
bool on_segment(Vec2 p, Vec2 a, Vec2 b);

// The closed segments ab and cd have a common point.
bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// p lies in the closed triangle abc (abc not degenerate, either turn).
bool in_closed_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c);

// A segment with endpoint keys (vertex ids): segments that share a key are
// allowed to meet at that endpoint only.
struct KeyedSegment {
  Vec2 a, b;
  int ka = -1, kb = -1;
};

// The two segments meet somewhere other than at an endpoint key they share
// (sharing both keys, i.e. the same edge twice, always conflicts).
bool segments_conflict(const KeyedSegment& s, const KeyedSegment& t);

// Some pair (i, j), i < j, of conflicting segments, or nullopt. Sweep over x
// with bounding-box filtering; deterministic for a given input order.
std::optional<std::pair<int, int>> find_segment_conflict(const std::vector<KeyedSegment>& segments);

enum class PointInLoop { Inside, Boundary, Outside };

// Even-odd location of p with respect to the closed polygon through
// pts[loop[0]], pts[loop[1]], ... Tie rule (a symbolic perturbation): the
// horizontal ray from p towards +x is taken at height p.y + epsilon, so a
// loop vertex with y == p.y counts as below the ray. Boundary when p is on an
// edge (exact).
PointInLoop locate_in_loop(Vec2 p, const std::vector<Vec2>& pts, const std::vector<int>& loop);

// The ray of locate_in_loop (from p towards +x at height p.y + epsilon)
// crosses the edge uw. Precondition: p is not on uw. Exact.
bool ray_crosses_edge(Vec2 p, Vec2 u, Vec2 w);

// Exact turn of a simple loop (no repeated or touching parts): the turn at its
// lexicographically smallest vertex (a convex corner). Positive = counter-clockwise.
Sign loop_turn(const std::vector<Vec2>& pts, const std::vector<int>& loop);

// Signed area (a construction), positive for counter-clockwise loops.
double loop_signed_area(const std::vector<Vec2>& pts, const std::vector<int>& loop);

}  // namespace pqmesh::detail
