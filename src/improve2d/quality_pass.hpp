#pragma once
// The 2D quality pass (docs/algorithm/improve2d.md), shared by both 2D meshers:
// the chapter-5 triangulator's post-pass (docs/algorithm/nosteiner2d.md
// "Fallbacks and the CDT comparison": the thesis bounds the min angle of its
// construction by a constant times g(P), but the constant is small) and the
// default mesh's improvement stage (quad2d/improve_mesh.hpp, with a target).
//
// Without a target (QualityPassOptions::target), after a first coarsening
// sweep, the pass repeatedly takes the triangle with the smallest angle and applies
// the one local change that raises the smallest angle of the triangles it
// replaces the most (strictly above that triangle's angle, else it stops):
//   * flip an interior edge of the triangle (the two triangles of a strictly
//     convex quadrilateral; a boundary edge has one triangle and is never flipped);
//   * remove a Steiner vertex of the triangle: its star (a simple polygon,
//     star-shaped from the vertex) is re-triangulated without it by the
//     triangulation of that polygon with the largest min angle (dynamic
//     programming over all its triangulations, diagonals decided by exact
//     orient2d);
//   * move a Steiner vertex of the triangle inside the kernel of its star
//     (compass search on the star's min angle from the better of the current
//     position and the centroid of the star's polygon);
//   * only when none of these helps: empty a disk of 4, 8, ..., 64 triangles
//     grown from the worst one (breadth first) of its inner (Steiner)
//     vertices and re-triangulate its boundary polygon as above;
//   * when nothing helps: coarsen around it - remove every Steiner vertex of
//     the 256 triangles nearest to it (breadth first; 2048 when none of those
//     is) whose star polygon has a triangulation with all angles above the
//     mesh's smallest, then retry;
//   * when none is removable: empty the first 4, 8, 16, ... triangles around
//     it (breadth first, any topology: holes and pinched vertices allowed) of
//     their inner (Steiner) vertices and re-triangulate by the CDT of the
//     cavity's boundary (cavity_cdt.hpp); the first whose smallest new angle
//     exceeds the worst one's is applied; stop when none does. The last
//     candidate is the whole mesh: its boundary edges are the input segments
//     and its inner vertices all the Steiner points, so its re-triangulation
//     is the CDT of P. Hence the pass never stops below the CDT's min angle
//     (it can still stop there on the step bound; never seen).
// With a target: coarsening and smoothing sweeps, then the single changes
// above at the worst triangle while it is below the target (no cavities, no
// coarsening when stuck); see QualityPassOptions::target.
//
// Invariants (every accept decided by exact orient2d on the stored doubles):
// every triangle stays strictly counter-clockwise; vertices with id <
// first_steiner (the input vertices, the only ones on dP) are never moved or
// removed, and no edge with one triangle (a boundary edge) changes, so no
// Steiner point reaches dP and dP stays split exactly at the input vertices.
// A moved vertex stays strictly inside the polygon of its star, which lies in
// P. Without a target the smallest angle of the mesh never decreases; with
// a target theta it never falls below min(theta, its value before) (floating
// point angles compared without tolerance: a measurement that chooses, never
// a validity decision). Deterministic: ties go to the first candidate in the order
// flips (edge order of the triangle), removals, moves (vertex order). Bounded:
// at most max_steps accepted changes.
#include <array>
#include <cstdint>
#include <vector>

#include "pqmesh/mesh.hpp"

namespace pqmesh::detail {

struct QualityPassStats {
  double min_angle_before = 0, min_angle_after = 0;  // radians
  std::int64_t flips = 0, removals = 0, moves = 0, cavities = 0, coarsened = 0, steps = 0;
  std::int64_t large_cavities = 0;  // CDT re-triangulated cavities of the last stage (cavity_cdt.hpp)
  bool stopped_stuck = false;  // stopped because no change raised the worst triangle (else: step bound)
};

struct QualityPassOptions {
  std::int64_t max_steps = -1;  // < 0: 4 * (vertex count) + 1000
  int max_star = 64;            // stars / cavities with more boundary vertices are not re-triangulated (the DP is cubic)
  int move_evaluations = 48;    // star evaluations per compass search
  int coarsen_triangles = 256;  // stuck: neighbourhood (triangles) whose removable Steiner vertices go
  bool large_cavities = true;   // stuck after coarsening: cavities of 4, 8, ... triangles up to the whole mesh
  // The objective. Negative (the default): the smallest angle of the mesh
  // alone; a removal is accepted when every new angle is above the mesh's
  // smallest, and when stuck the pass coarsens and empties cavities. A target
  // angle theta (radians, >= 0): every change keeps the quality of the
  // triangles it replaces, up to theta: its smallest new angle is above
  // min(theta, the smallest replaced angle); the worst-first loop stops once
  // the worst triangle reaches theta, and when no single change helps it stops
  // (no coarsening, no cavities). With theta, the smallest angle never falls
  // below min(theta, its value before), and no triangle that met theta is
  // replaced by one that does not.
  double target = -1;
  // After the first coarsening sweep: rounds of a smoothing sweep followed,
  // with a target and coarsen, by another coarsening sweep (smoothing makes
  // room for removals), then final smoothing sweeps. A smoothing sweep moves
  // each Steiner vertex whose star's smallest angle is below smoothing_below
  // (radians), in id order, to the best position of its star (compass search)
  // when that raises the star's smallest angle.
  int smoothing_rounds = 0;
  int final_smoothing_sweeps = 0;
  double smoothing_below = 0;
  // false: no vertex is removed (only moves and flips).
  bool coarsen = true;
  // Per vertex (empty: none): a boundary vertex the coarsening sweeps may
  // remove, merging its two boundary pieces (mesh.edges, directed with the
  // domain on their left) into one when it lies exactly on the line through
  // its two boundary neighbours (exact orient2d), so the domain is unchanged.
  // For Steiner points inside an input segment only.
  std::vector<char> boundary_removable{};
};

// Improves `mesh` in place (triangles, triangle_markers, vertices,
// vertex_markers; unused Steiner vertices are dropped at the end and the rest
// renumbered in order, mesh.edges renumbered with them; ids < first_steiner
// are unchanged). Triangles made by a change take the marker of the triangle
// it started from. A vertex is changed only when its star is a disk around it
// (never a vertex of a boundary edge) and its id is >= first_steiner, and no
// boundary edge changes, so mesh.edges stay edges of the mesh.
QualityPassStats improve_min_angle(TriMesh2& mesh, int first_steiner, const QualityPassOptions& options = {});

}  // namespace pqmesh::detail
