#pragma once
// Thesis §5.4 "Match faces": the match edges join every Q vertex to its R
// vertices (one in Case 1, two in Case 2 of §5.2) and cut Q \ R into one
// match trapezoid per Q side E (E and its shrunk side F, parallel) and one
// match triangle per Case 2 Q vertex V (V and its shrunk side F). Each figure
// is indexed like the R side F it contains (R loop l, side j), so the figure
// across the match edge at F's start is side j - 1 and at its end side j + 1.
#include <vector>

#include "pqmesh/mesh.hpp"
#include "nosteiner2d/stages.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::detail {

struct MatchFigure {
  bool is_triangle = false;  // match triangle (Case 2 vertex) or match trapezoid
  int loop = -1, side = -1;  // R loop and side j (= the Q loop)
  // Counter-clockwise outline p -> q -> b -> a (triangle: p == q == V, the
  // outline V -> b -> a): E = p -> q is the Q side, F = a -> b the R side,
  // a -> p and b -> q the match edges (§5.4).
  Vec2 p, q, a, b;
  int p_id = -1, q_id = -1;  // ids in the combined numbering of match_qr.hpp
  // R's mesh vertices on F in order from a to b (both included): combined ids and points.
  std::vector<int> f_ids;
  std::vector<Vec2> f;
  double delta = 0;          // delta of F's source face in Q (delta(E), or delta(V) for a triangle)
  double length = 0;         // L(E); for a triangle, L(F)
  double scale = 0;          // the Lemma 45-47 angle scale: delta(E)/L(E); triangle: min over the two
                             // neighbouring trapezoids (§5.4.2, min of delta(H)/L(H))
  int prev = -1, next = -1;  // figure indices across the match edges at a and at b
};

// Throws InternalError when R's mesh boundary does not pass through R's loop
// vertices in loop order. nq = q.wedges.vertices.size().
std::vector<MatchFigure> match_figures(const PolygonQ& q, const PolygonR& r, const TriMesh2& r_mesh);

}  // namespace pqmesh::detail
