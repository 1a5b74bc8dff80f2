#pragma once
// Thesis §5.4 "Matching R to Q": the triangles of Q \ R (the region between
// dQ and dR), with Steiner points only strictly inside Q \ R. dQ is kept
// unsplit (the thesis adds "Steiner points to a figure's interior and to its
// sides, but not to any edge of R or Q"), so Q^c needs no change; dR keeps
// exactly the subdivision of R's mesh.
//
// Stages (docs/algorithm/nosteiner2d.md "Matching R to Q";
// src/nosteiner2d/match_*.cpp):
//  1. match_figures.cpp: the match edges (each Q vertex to its R vertices)
//     cut Q \ R into one match trapezoid per Q side E (E, its shrunk side F)
//     and one match triangle per Case 2 Q vertex (§5.4 "Match faces"); the
//     mesh vertices of R on F, in order, are read off R's mesh boundary.
//  2. match_squares.cpp: per figure, the square drawing of §5.4.1 with
//     levels (balanced) and elongation (Lemmas 38-42): guide lines M_j at
//     the fraction 2^-j of the way from F to E (height d / 2^j in a
//     trapezoid), the squares of step i with their top on M_{n-i+1}; square
//     corners on a match edge are put on the match edge ("we use the match
//     edge for a side"). Match triangles (§5.4.2) use the same drawing with
//     the apex as both Q ends. n is chosen from the edges on F
//     (match_squares.hpp).
//  3. match_qr.cpp: the triangles. The vertex set is dQ, R's mesh vertices on
//     dR and the square vertices; the connectivity (MatchOptions) is by
//     default the constrained Delaunay triangulation of Q \ R on that vertex
//     set, with every side of dQ and every mesh edge of dR as a constraint
//     (by Lawson's optimality its min angle is at least that of any
//     triangulation of the same vertices with the same constraints, the
//     thesis's among them), or the thesis's per-piece fans of Figs. 5.17,
//     5.19-5.21 (match_fans.hpp; measured 0.33-1 times the CDT's). Match edges are
//     not constraints: the figures on the two sides of a match edge put
//     their corners on it at heights 2^-j, and equal heights give the same
//     rounded point, which is one vertex ("adjacent figures share sides").
//
// Exactness (docs/DESIGN_RULES.md "Exact decisions"): constructions (square
// vertices) are rounded; every decision on them is exact: a square vertex is
// kept only when orient2d puts it in the closure of its figure, or of its
// neighbour across the match edge it was put on, strictly off dQ and dR; a
// point with the coordinates of a kept one is that vertex. Levels are a
// construction choice from rounded lengths, not a geometric decision.
#include <array>
#include <cstdint>
#include <vector>

#include "pqmesh/mesh.hpp"
#include "nosteiner2d/stages.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

struct MatchStats {
  std::int64_t trapezoids = 0, triangles_fig = 0;  // match trapezoids / match triangles (figures)
  std::int64_t squares = 0;                        // squares drawn (§5.4.1), all figures
  std::int64_t candidates = 0;                     // square vertices constructed
  std::int64_t dropped = 0;                        // of those, not strictly inside Q \ R (rounding)
  std::int64_t shared = 0;                         // of those, already given (the same point on a match edge)
  int max_steps = 0;                               // largest n (guide lines) of one figure
  // Elongation (Lemmas 38, 39, 42) over all squares: max over squares not at
  // the right end of F, max at the right end, min over all.
  double max_elongation_inner = 0, max_elongation_right = 0, min_elongation = 0;
  std::int64_t lemma41_violations = 0;  // items not drawn around at step l or l+1 (l = their level)
  std::int64_t level_raises = 0;        // triangulation edges whose length level was raised for balance
  double min_angle = 0;                 // radians, over the returned triangles
  // (The fields below describe §5.4's construction, also when the plain CDT is returned.)
  double min_delta_over_length = 0;  // min over trapezoids of delta(E)/L(E) (Lemmas 45-46 scale)
  // Lemmas 45-47 measured: min over triangles of angle / scale, where the
  // scale of a triangle is the smallest MatchFigure::scale (delta(E)/L(E))
  // over the figures its vertices belong to.
  double min_angle_over_scale = 0;
  // Lemmas 43-44: the interior angles of the match trapezoids at R's
  // vertices, i.e. between a match edge and F (radians): min (>= pi/4 + kA)
  // and max (<= pi - kA). The proofs are about trapezoids (Case 1 / Case 2
  // corners of §5.2 seen from the side E); the construction gives them
  // directly: the trapezoid's angles at a and p sum to pi (E parallel to F),
  // and the angle at p is < 3 pi/4 (Case 1: a part of the corner angle
  // <= 3 pi/4) or the ray angle beta <= 3 pi/4 (Case 2), so min > pi/4.
  double min_match_angle = 0, max_match_angle = 0;
  // The same angles in the match triangles (§5.4.2): they sum to pi/2 at the
  // two R vertices and the thesis bounds them only by a constant times
  // min(delta(H)/L(H)) of the neighbouring sides, not by pi/4.
  double min_match_angle_triangle = 0, max_match_angle_triangle = 0;
  double cdt_min_angle = 0;      // the CDT of Q \ R without the square vertices (no square vertices)
  double squares_min_angle = 0;  // the CDT with the square vertices (§5.4's construction)
  bool used_plain_cdt = false;   // the output is the plain CDT (MatchOptions::keep_better)
  // Connectivity::Fans: pieces triangulated by the thesis's fan, pieces whose
  // fan was not valid (their own CDT), and figures left to the CDT of Q \ R
  // (the drawing gave no pieces: never expected).
  std::int64_t fans = 0, polygon_cdts = 0, figures_not_fanned = 0;
  double fans_min_angle = 0, polygon_cdts_min_angle = 0;  // radians, over those pieces (10: none)
};

struct MatchOptions {
  // Return the plain CDT of Q \ R (no Steiner point) instead when its min
  // angle is strictly larger than that of §5.4's construction (an addition
  // to the thesis: it only raises the min angle, so the bound of Lemmas
  // 45-47 still holds for the output).
  bool keep_better = true;
  // Connectivity of §5.4's construction: the thesis's per-piece fans
  // (Figs. 5.17, 5.19-5.21, match_fans.hpp), or the constrained Delaunay
  // triangulation of Q \ R on the same vertices. By Lawson's optimality the
  // CDT's min angle is at least the fans' (same vertices, same constraints
  // dQ and dR), so the fans are the thesis's construction and the CDT the
  // better output; both are measured (match_qr_test.cpp).
  enum class Connectivity { Fans, Cdt } connectivity = Connectivity::Cdt;
};

// Always empty: dQ is never split (kept for the caller's assembly).
struct QSideSplit {
  int loop = -1, side = -1;  // Q loop and side k -> k+1
  std::vector<Vec2> points;  // split points in order from k to k+1
};

struct MatchQR {
  // Steiner points, all strictly inside Q \ R.
  std::vector<Vec2> points;
  // Counter-clockwise triangles covering exactly the closure of Q \ R. Ids:
  //   [0, nq)              q.wedges.vertices (nq = its size; dQ = q.loops);
  //   [nq, nq + nr)        r_mesh.vertices[id - nq] (nr = its size);
  //   [nq + nr, ...)       points[id - nq - nr].
  // This is the numbering of "Q^c vertices, then R's mesh vertices, then the
  // rest", so the caller appends `points` and the triangles as they are.
  std::vector<std::array<int, 3>> triangles;
  std::vector<QSideSplit> q_side_splits;  // empty (see above)
  MatchStats stats;
};

// q: Q with Q^c (polygon_q). r: shrink_q_to_r(q_loop_points(q)) (valid,
// representable). r_mesh: a mesh of polygon_r_domain(r) (quad_mesh(...).mesh),
// whose vertices include R's loop vertices with identical coordinates.
// Throws InternalError when R's mesh boundary does not pass through R's loop
// vertices in loop order, or when the CDT fails (dQ and dR meet).
MatchQR match_q_to_r(const PolygonQ& q, const PolygonR& r, const TriMesh2& r_mesh, const MatchOptions& options = {});

}  // namespace pqmesh::detail
