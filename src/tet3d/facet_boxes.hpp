#pragma once
// Tetrahedra of empty boxes (§4.5.1), facet boxes (§4.5.4), edge boxes
// (§4.5.3), vertex boxes (§4.5.2) and two-facet boxes (§4.5.5), optionally
// with warped box vertices (§4.3, warp.hpp; a box corner exactly on F is
// never moved and is then its own crossing point, cut_square.hpp). Every box face square goes through the
// square dispatcher (square_cases.hpp), so all kinds share one triangulation
// of every square.
//
// Facet box b (facet F, §4.5.4), d the box centre's signed distance to F's
// plane: d <= -h/4: the centre coned to the π-triangles and to the fan of
// F ∩ b from a central point g of it; |d| < h/4: the centre moved onto F,
// coned to the π-triangles; else prisms (cones from the centre clipped by
// F). g: the vertex mean of F ∩ b, unless its worst fan tetrahedron is worse
// than the box's worst cone; then the polygon's area centroid or its
// boundary's length-weighted centroid if better, every fan tetrahedron
// positive by exact orient3d (fan_centre in facet_polygon.cpp).
// Edge box b (edge E, facets F, G): v = the midpoint of E ∩ I(b), i.e. of the
// box's two Case B vertices where E enters and leaves it (wherever the square
// code put them, warped_crossing.hpp; the midpoint of E ∩ the prewarped cube
// if they are not two), rounded within an ulp of E (edge_point.hpp), coned to every π-triangle of
// b's faces. Our choice: when a point at 1/4, 3/8, 5/8 or 3/4 of E ∩ I(b)
// gives a better worst cone (every cone positive, exact), v is that point
// instead (a chord of F or G on a box face whose line meets E near the
// midpoint makes the boundary triangle of that chord and v nearly flat).
// P ∧ b = cube ∩ wedge(E) is star-shaped from every point of E in the open
// cube, so the cones tile it; their faces through v on F and G are the
// boundary triangles there.
// Vertex box (P vertex v, its united 2x2x2 box B, §4.1.3; the job names the
// leaf holding v and which side B extends to): v coned to the π-triangles of
// B's outer faces (squares of the finer side); B's inner leaves are not meshed
// one by one (box_jobs.hpp leaves them out; leaves of another component
// inside B have their own jobs). v's component P ∧ B = cone(v) ∩ B is
// star-shaped from v, which lies strictly inside B (Lemma 1; checked
// exactly). A square of B meeting no face takes its status (inside / outside)
// from the ring points it shares with squares that do, decided by their local
// models (square_cases.hpp), propagated over B's surface.
//
// Jobs from an octree: box_jobs.hpp. Per-component: each job is one tree node
// (one component of a duplicated cube, §4.1.1), with the faces of its kind.
// Two-facet box (facets F, G of an edge E outside the box, §4.5.5). With
// H_F, H_G P's sides of the two planes, P ∧ b = cube ∩ H_F ∩ H_G (convex E)
// or cube ∩ (H_F ∪ H_G) (reflex E; star-shaped from the kernel H_F ∩ H_G).
//   centre strictly in H_F ∩ H_G, and (reflex, or at least h/4 from both
//   planes): v = the centre, coned to the π-triangles of the faces and to the
//   fans of F ∩ b and G ∩ b from their vertex means (as the facet box's
//   "inside" case);
//   otherwise, convex E: v is put on the facet whose plane is nearer the box
//   centre, at the mean of the vertices of the polygon F ∩ b (a point of its
//   relative interior, rounded onto F), and coned to the π-triangles and to
//   the fan of the other facet's polygon; the other facet's polygon mean is
//   taken instead when every one of its tetrahedra is positive (exact
//   orient3d) and their worst shape is strictly better (tet_shape; a thin
//   polygon almost in a box face made flat cones). Deviation: the thesis
//   projects the centroid onto F when within h/4 and otherwise keeps it
//   (possibly outside P, with prisms); the projection may miss F ∩ b, the
//   polygon mean cannot, and cones from a boundary point of a convex polytope
//   always tile it, so no prism is needed;
//   otherwise (reflex E, centre outside the kernel): InternalError (not done).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/squares/square_cases.hpp"
#include "tet3d/points/vertex_key.hpp"
#include "tet3d/warp/warp_table.hpp"

namespace pqmesh::tet3d {

struct BoxJob {
  std::int32_t leaf = -1;
  int facet = -1;  // kind FromFacet: the facet box's facet; -1: an empty box
  BoxKind kind = BoxKind::FromFacet;
  // Facet: facet id; Edge, TwoFacet: index into Domain3::edges; Vertex: P vertex id.
  int apex = -1;
  // Vertex: bit a set when the united box extends one leaf side below the
  // leaf along axis a (else above); the united box is 2x2x2 leaves.
  std::uint8_t block = 0;
};

struct FacetBoxStats {
  std::int64_t empty = 0, inside = 0, on_facet = 0, beyond = 0;  // boxes per case
  // Empty boxes made of six Kuhn tetrahedra, and Kuhn faces (cut by one
  // diagonal) counted once per asking empty box (empty_box.cpp).
  std::int64_t empty_kuhn = 0, kuhn_faces = 0;
  std::int64_t edge = 0, vertex = 0, two_facet = 0;              // boxes of the other kinds
  std::int64_t edge_apex_moved = 0;     // edge boxes whose apex is not E's midpoint (edge_box.cpp apex_on_edge)
  std::int64_t edge_two_apex = 0;       // edge boxes coned from v on E and a second point (edge_box.cpp two_apex_box)
  std::int64_t edge_two_apex_flat = 0;  // the same, where v's cones were flat (edge_box.cpp flat_two_apex)
  std::int64_t edge_facet_fans = 0;     // edge boxes with flat cones from v made by edge_box_fans.cpp
  std::int64_t two_facet_centre = 0;    // two-facet boxes coned from their centre (the rest: from a facet)
  std::int64_t two_facet_reflex = 0;    // two-facet boxes at a reflex edge (all coned from their centre)
  // Two-facet boxes coned from the facet whose plane is farther from the
  // centre (two_facet_box.cpp two_facet_apex).
  std::int64_t two_facet_apex_farther = 0;
  // Squares per dispatcher case (SquareCase: nothing, A, C, B/D), counted
  // once per asking box (a shared square is counted from both sides).
  std::int64_t squares_nothing = 0, squares_a = 0, squares_c = 0, squares_bd = 0;
  // Vertex-box squares split into one piece per plane group (SquareCase::Pieces;
  // each piece is also counted under its own case above).
  std::int64_t squares_pieces = 0;
  // Vertex-box squares meeting no face: decided from neighbouring squares'
  // local models / by locate() (none expected).
  std::int64_t vertex_squares_by_neighbours = 0, vertex_squares_located = 0;
};

struct BoxMesh;

struct BoxMeshOptions {
  // §4.3 warping (both passes) for the box vertices of every kind (warp.hpp;
  // rules and counts there).
  bool warp = false;
  // Hand the final warp table to BoxMesh::warps (measurements: Lemma 6's
  // clearances of box vertices outside P, which are no mesh vertices).
  bool keep_warp_table = false;
  // With warp: called once, after the first warp table, with the tetrahedra
  // at its stuck corners (rebuild/stuck_corners.hpp); a non-empty answer
  // stops the run before the rebuild loop: mesh_boxes returns an empty mesh
  // with BoxMesh::stuck set to it. Empty: not called.
  std::function<std::string(const BoxMesh&)> stuck_review;
};

namespace detail {
// Switches that turn off one stage of mesh_boxes, for tests only: the
// production path (tet_mesh) never passes them, so every stage is on. Each
// exists because a test checks a property that needs the stage off:
struct BoxMeshTestHooks {
  // Fig. 4.7's copies per facet for box vertices in a reflex edge's slot
  // (warp.hpp); false: such a vertex stays in place (counted in
  // warp_reflex_left), which shows that the test domain puts vertices in
  // the slot (reflex_slot_copies_test.cpp).
  bool reflex_copies = true;
  // The rebuild loop's trials after a rebuild run only the jobs the new table
  // can change (trial_scope.hpp); false: every trial runs every job. Both
  // must give the same mesh (rebuild_loop_test.cpp).
  bool partial_trials = true;
  // After the rebuild loop, a table whose worst tetrahedron is flat gets the
  // warps of its worst box frozen while that strictly improves the worst
  // tetrahedron (worst_box_freeze.hpp); false: the rebuild loop's table is
  // kept. A run below the threshold must be unchanged by the freeze
  // (worst_box_freeze_test.cpp).
  bool freeze_worst_box = true;
  // Edge boxes with flat cones from the apex on E may fan F ∩ b and G ∩ b
  // from points of their own facets (edge_box_fans.cpp); false: only the
  // two-point construction is tried there, so that a test can bound that
  // construction alone (flat_cone_two_apex_test.cpp).
  bool facet_fans = true;
  // When the two-cone-point run loses, the first run's mesh is remade from
  // its final warp table in one pass over the jobs (facet_boxes.cpp
  // remake_pass); false: the first run is made again whole. Both must give
  // the same mesh (two_cone_points_test.cpp).
  bool remake_from_table = true;
  // The rebuild loop's tables after the first, when the edge boxes are
  // unchanged, are made from the last one (warp.hpp rewarp_box_vertices);
  // false: each is built whole. Both must give the same mesh
  // (rewarp_test.cpp).
  bool incremental_tables = true;
};
}  // namespace detail

struct BoxMesh {
  TetMesh3 mesh;                       // region attribute 0; no boundary face list
  std::vector<VertexKey> keys;         // per vertex
  std::vector<std::int32_t> tet_leaf;  // per tetrahedron
  std::vector<std::int32_t> tet_job;   // per tetrahedron: index into the jobs
  FacetBoxStats stats;
  // Second warping pass (warp.hpp): vertices moved (of which onto an acute
  // wedge's bisector), and left in place: side conflict, in a reflex edge's
  // slot with a Fig. 4.7 copy refused, crowded, would invert a tetrahedron
  // (frozen, facet_boxes.cpp); not moved: exactly on a facet plane. Slot
  // vertices with both Fig. 4.7 copies built (not among `warped`).
  std::int64_t warped = 0, warp_conflicts = 0, warp_bisected = 0, warp_fallback = 0, warp_reflex_left = 0,
               warp_crowded_left = 0, warp_on_plane = 0, warp_inverting_left = 0, warp_reflex_copied = 0;
  // First pass (box edges near P edges): vertices moved by it (among
  // `warped`), and first-pass moves not made (box edge parallel to E).
  std::int64_t warp_first_pass = 0, warp_parallel_left = 0;
  std::int64_t warp_parallel = 0;   // first-pass moves of box-edge pieces parallel to E
  std::int64_t warp_centres = 0;    // square centres carried with their corners (among `warped`)
  std::int64_t warp_rebuilds = 0;   // warp tables rebuilt after freezing points of inverted tetrahedra
  std::int64_t worst_box_rounds = 0;  // worst-box freeze rounds kept (worst_box_freeze.hpp)
  // Box stages run: 1; 2 when the two-cone-point run was made and kept; 3 when
  // it lost and the first run's mesh was remade (mesh_boxes).
  std::int64_t box_runs = 1;
  // The out-of-face table (docs/algorithm/tet3d_warp.md "One decision per
  // shared face"): 0 not tried, 1 tried and lost, 2 kept.
  std::int64_t wider_table = 0;
  std::int64_t warp_shortened = 0;  // moved by a fraction of a refused second-pass move (warp.hpp; among `warped`)
  std::shared_ptr<const WarpTable> warps;  // the final table, with BoxMeshOptions::keep_warp_table
  // BoxMeshOptions::stuck_review's answer when it stopped the run (the mesh
  // is then empty); else empty.
  std::string stuck;
};

// The squares of the job's box faces (face order (axis 0..2) x (lower,
// upper)): the leaf's faces, or the united box's (2x2x2 leaves) for a vertex job.
void job_squares(const OctTree& tree, const CornerSet& corners, const BoxJob& job, std::vector<FaceSquare>& out);
// The squares of face (axis, upper) of the united box of a vertex job.
void united_face_squares(const BoxKey<3>& key, std::uint8_t block, int axis, bool upper, const CornerSet& corners,
                         std::vector<FaceSquare>& out);
GridPoint united_lo(const BoxKey<3>& key, std::uint8_t block);
// The P faces the square dispatcher sees for the job's box.
BoxFaces job_faces(const SquareDispatcher& squares, const BoxJob& job);

BoxMesh mesh_boxes(const OctTree& tree, const CornerSet& corners, const Domain3& domain, std::span<const BoxJob> jobs,
                   const BoxMeshOptions& options = {}, const detail::BoxMeshTestHooks& hooks = {});

}  // namespace pqmesh::tet3d
