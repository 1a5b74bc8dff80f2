#pragma once
// Thesis §5.4.1 "Drawing squares" (and §5.4.2 for match triangles): the
// vertices of the squares drawn in one match figure, with the levels and the
// elongation of Lemmas 38-42 measured.
//
// Frame. A point of the figure is x(u, t) = L(t) + u (R(t) - L(t)) with
// L(t) = a + t (p - a) and R(t) = b + t (q - b) on the two match edges:
// t = 0 is F, t = 1 is E (a triangle's apex), and for a trapezoid the set
// t = const is the segment of the line parallel to F at height t d. u is the
// fraction along F. The guide line M_j is t = 2^-j (height d / 2^j, §5.4.1).
// A square spans [u0, u1] x [0, t_top]; its sides are the segments u = u0 and
// u = u1, which for u0 = 0 (u1 = 1) is the match edge itself, as the thesis
// asks when a square reaches a match edge ("we use the match edge for a
// side"); inner sides interpolate between the two match edges (deviation
// from perpendicular sides: the same where the match edges are
// perpendicular to F, and inside the figure everywhere).
//
// Levels (deviation: quad_mesh does not expose its quadtree, so the size
// q(G) of the box holding a mesh edge G of F is replaced by L(G)): with h0
// the shortest edge on F, l(G) = 1 + floor(log2(L(G) / h0)) (exact, from
// the binary exponent of the rounded ratio). The thesis's special size of
// the box at a vertex of F (as large as its neighbour's) is applied to the
// two end edges, and the balance the thesis takes from the quadtree
// (adjacent levels differ by at most one, which Lemmas 40-42 use) is
// enforced by raising levels: l_i = max_k (l_k - |i - k|).
//
// Steps (§5.4.1): n = max(max level, floor(log2(L(F) / h0)) - 1), capped
// at kMaxSquareSteps. The thesis has n = floor(log(L(E)/d)) with its
// h0 ~ k1 d, so that M_1 holds a constant number of edges; here h0 can be
// far below d (§5.5.1 property 1 is only ~0.006 delta,
// docs/algorithm/nosteiner2d.md "Meshing R") and n is taken from h0 so that the
// squares of the last step span about 2 to 4 of them. Measured (data/2d and
// random polygons): minus one doubles the min angle against
// floor(log2(L(F)/h0)); minus two and plus one are worse, and so are other
// heights for M_1 than d/2. At step i every maximal run C of consecutive items
// of level <= i (m = |C| > 1) gets squares around items (0,1), (2,3), ..., the
// last skipped when m is odd, unless C ends with the last item of S, when the
// last square takes three. A square of step i has level i + 1, its top on
// M_{n-i+1}, and replaces its items in S.
#include <cstdint>
#include <vector>

#include "nosteiner2d/match_figures.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

inline constexpr int kMaxSquareSteps = 60;

// A square vertex: where it lies in the figure's frame.
struct SquarePoint {
  Vec2 point;
  double u = 0, t = 0;
  enum class On { Inside, StartEdge, EndEdge } on = On::Inside;  // on the match edge at a (u = 0) / at b (u = 1)
};

// An item of S in the frame: [u0, u1] at height t = height (0 for a mesh
// edge of F, the top t of a square).
struct FrameItem {
  double u0 = 0, u1 = 1, height = 0;
};

// A drawn square: [u0, u1] x [below its items, t_top]; its bottom is the
// staircase of the items it was drawn around (left to right). centre: the
// centre vertex of a square around three mesh edges (Fig. 5.20), else unset.
struct DrawnSquare {
  double u0 = 0, u1 = 1, t_top = 0;
  std::vector<FrameItem> items;
  bool has_centre = false;
  double centre_u = 0, centre_t = 0;
};

struct SquareDrawing {
  std::vector<SquarePoint> points;     // corners (top corners of every square) and centre vertices
  std::vector<double> f_u;             // u of F's mesh vertices (a = 0 .. b = 1), as the items use them
  std::vector<DrawnSquare> drawn;      // every square, in the order drawn (smaller steps first)
  std::vector<FrameItem> final_items;  // S after step n: the bottom of the region below E (§5.4.1)
  int steps = 0;                       // n
  std::int64_t squares = 0;
  std::int64_t level_raises = 0;        // end-edge rule and balance
  std::int64_t lemma41_violations = 0;  // an item of level l drawn around after step l + 1, or never
  double max_elongation_inner = 0;      // Lemma 38: <= 1
  double max_elongation_right = 0;      // Lemma 39: <= 2 (squares containing F's last vertex)
  double min_elongation = 0;            // Lemma 42: >= 1/2 (0 when no square)
};

SquareDrawing draw_squares(const MatchFigure& figure);

// x(u, t) of the frame above (a rounded construction).
Vec2 figure_point(const MatchFigure& figure, double u, double t);

}  // namespace pqmesh::detail
