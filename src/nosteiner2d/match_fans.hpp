#pragma once
// Thesis §5.4.1 "Triangulation of squares" (Figs. 5.19-5.21) and the region
// between M_1 and E (Fig. 5.17; §5.4.2 for match triangles): the triangles of
// one match figure, square by square, on the vertices the square drawing
// kept (match_qr.cpp). No vertex is added here.
//
// In the figure's frame (match_squares.hpp) every piece is a polygon whose
// sides lie on the lines u = const and t = const, which the frame maps to
// straight segments; a side lists every kept vertex on it (F's mesh vertices,
// the corners of smaller squares next to it, the neighbouring figure's
// corners on a shared match edge), so neighbouring pieces conform.
//  * A square's polygon: the staircase of its items (heights 0 for mesh
//    edges, the top of a smaller square otherwise), its right side, its top
//    on M_{n-i+1}, its left side. Centre vertex (Fig. 5.19): for a square
//    around two items the vertex between them at the higher of their two
//    tops (the thesis's "leftmost vertex of the rightmost edge of level i",
//    or the rightmost of the leftmost; we take the one at the higher top,
//    the reflex corner, from which the L-shaped polygon is star-shaped); for
//    three mesh edges the centre vertex of Fig. 5.20; for three items with
//    squares among them the item boundaries at the highest top, in order.
//    Fan: one triangle from the centre to every polygon side not incident to
//    it; the vertices on the sides (Fig. 5.21's match-edge vertices and
//    Fig. 5.20's side vertices) get their own triangle this way.
//  * The region above S after step n up to E: each vertex of its bottom and
//    of its sides is joined to the closer end of E, the one side whose ends
//    go to different ends of E gives the quadrilateral (p, x, y, q) split by
//    the diagonal with the larger min angle ("one more edge for the remaining
//    trapezoid"). Match triangle: the fan from its apex V.
// Exactness (docs/DESIGN_RULES.md "Exact decisions"): a fan is used only when
// exact orient2d puts every one of its triangles strictly counter-clockwise and
// every polygon side not incident to the centre is not collinear with it (else
// a vertex would be a T-junction). Otherwise (the thesis's six cases of Fig.
// 5.20 include squares whose low parts are not visible from one vertex) the
// polygon is triangulated by the constrained Delaunay triangulation of its own
// vertices and sides (counted in FanStats::polygon_cdts).
#include <array>
#include <cstdint>
#include <vector>

#include "nosteiner2d/match_figures.hpp"
#include "nosteiner2d/match_squares.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

// A kept vertex of the figure in its frame: (u, t) and its index into the
// caller's point array.
struct FrameVertex {
  double u = 0, t = 0;
  int point = -1;
};

struct FanStats {
  std::int64_t fans = 0;          // polygons triangulated by a fan (squares and the region below E)
  std::int64_t polygon_cdts = 0;  // polygons whose fan was not valid: their own CDT
  // Smallest triangle angle (radians) in the fanned pieces and in the pieces
  // given their own CDT (10 when there is none).
  double fans_min_angle = 10, polygon_cdts_min_angle = 10;
};

// figure: the match figure; drawing: draw_squares(figure); vertices: every
// kept vertex on the closed figure in its frame (F's mesh vertices at t = 0,
// p at (0, 1), q at (1, 1), the kept square vertices of this figure and of
// its neighbours on the shared match edges, mapped to u = 0 / u = 1);
// points: the caller's coordinates. Appends counter-clockwise triangles
// (indices into points) covering the figure. Returns false (appending
// nothing) when the drawing gives no pieces (no squares and no items).
bool triangulate_figure_by_fans(const MatchFigure& figure, const SquareDrawing& drawing,
                                const std::vector<FrameVertex>& vertices, const std::vector<Vec2>& points,
                                std::vector<std::array<int, 3>>& triangles, FanStats& stats);

}  // namespace pqmesh::detail
