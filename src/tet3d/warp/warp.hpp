#pragma once
// Thesis §4.3, both warping passes, for the box vertices of every box kind
// (empty, facet, edge, vertex, two-facet), as one table: grid point -> moved
// coordinates, computed before any box is meshed (docs/algorithm/tet3d_warp.md
// "The two passes"). h of a vertex: the smallest box containing it
// (CornerSet::finest_level, or the deepest job box whose faces use it,
// WarpCandidate::level). Distances and directions are constructions
// (floating-point thresholds, as in 2D, docs/algorithm/quad2d.md "Mesh vertices
// and warping": either outcome is valid, only quality moves); every decision
// that shapes the mesh stays exact.
//
// First pass: a ring segment [v, w] (a piece of a box edge: our box edges are
// chains of split points) closer than h/8 to a P edge E between two facets of
// the boxes using v moves h/8 orthogonally to E and to the segment, away from
// E; moves of distinct (axis, E) pairs add up. E parallel to the box edge:
// h/8 along the common perpendicular of the two lines, away from E (the
// thesis: "orthogonal to E and coplanar with" the P edge; `parallel`); E on
// the box edge's line has no such direction: left (`parallel_left`).
// Second pass, from the first pass's position:
//   * v exactly on the plane of a facet of a box using it (orient3d = 0, on
//     the prewarped point) is not moved at all (an exact boundary point);
//   * one close facet (distance to the facet itself <= h/16): h/16 along its
//     normal, away from it;
//   * two close facets F, G of one P edge E, convex (acute interior wedge),
//     v strictly on P's side of both: orthogonal projection onto the plane
//     bisecting the wedge ((n_F - n_G)·(x - a) = 0, a on E);
//   * both close, v in the exterior slot of a reflex edge (Fig. 4.7): no
//     entry, one copy per facet (warp_table.hpp), each h/16 along its own
//     facet's normal, away, accepted by the rules below except the side of
//     the partner facet (`reflex_copied`; a copy refused: `reflex_left`);
//   * both close elsewhere near E: h/16 along the sum of the two normals
//     oriented to v's sides (beyond the thesis); close to two facets without a
//     common edge or to three: left, counted (`crowded_left`).
// Acceptance: a move must change no decision made on the PREWARPED points:
// v's side of every facet of every box using v (a square's status and cut
// come from its ring's sides; which faces meet a square is decided on the
// prewarped square, square_meets.hpp, untouched), and for every ring segment
// [v, w] crossed by F or G of a P edge E of those boxes the side of E's line
// it passes (orient3d(a, b, v, w), Cases B/D, cut_square_edge.hpp), against
// w's current position. A refused full move falls back to the first pass
// alone, then to the second pass alone from the prewarped point
// (`fallback`), then to 1/2, 1/4, 1/8 or 1/16 of the second pass alone, if
// accepted and no nearer than the prewarped point to any facet of v's boxes
// (in units of h/16, capped at 1) and no ring segment from v nearer to a P
// edge between them (h/8), the smallest of these clearances larger
// (`shortened`); then (beyond the thesis, bounded seed 58) to v moved away from a
// ring neighbour w along the axis of [v, w], h/16 or 1/2 .. 1/16 of it, on
// the same rules and clearance test: [v, w] keeps its line, so its side of
// E's line and F's crossing of it are unchanged (`shortened`); else v stays
// (`conflicts`). The caller may freeze points
// whose move inverted a tetrahedron (`frozen`, facet_boxes.cpp).
//
// Square centres (beyond the thesis): the thesis keeps the centre c of a Case A
// square at the prewarped face centre, but the first pass moves whole box
// edges by h/8, so when every corner of a square moves alike (a face near a
// P edge) the face becomes a tent with c h/8 inside it, and an edge-box apex
// on E, also about h/8 from the prewarped face, lies nearly on a tent
// triangle's plane (plate_holes: aspect 6,170). c is carried with its square:
// moved by the mean of its four corners' moves (the centre of the bilinear
// patch through the warped corners), after all ring points; accepted when it
// keeps c's exact side of every facet of the boxes using the square (c on a
// plane is not moved), so every decision about c stays the prewarped one.
//
// Consistency: every box resolves its grid points through the table
// (grid_vertex, and PointBook for any Grid key: square centres are asked for
// by grid_key in the square code), so all boxes sharing v see one moved
// copy, keyed (Warped, v, F) (F = the first close facet, or -1).
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/points/point_book.hpp"
#include "tet3d/warp/warp_candidates.hpp"
#include "tet3d/warp/warp_table.hpp"

namespace pqmesh::tet3d {

// The candidates (WarpCandidate, WarpCandidates): warp_candidates.hpp.
// An edge box (§4.5.3): its grid bounds and its P edge.
struct EdgeBoxBounds {
  GridPoint lo, hi;
  int edge = -1;
};
// What a warp run is asked to leave, add or drop besides §4.3's two passes
// (the defaults: the thesis's passes with Fig. 4.7's copies, nothing frozen,
// no face translations, no reported points).
struct WarpOptions {
  // Points never moved (counted in frozen_left when they would be); null:
  // none. The set is the caller's and must outlive the call.
  const std::unordered_set<GridPoint, GridPointHash>* frozen = nullptr;
  // Fig. 4.7's copies per facet for a vertex in a reflex slot; false
  // (detail::BoxMeshTestHooks only): no copies, such a vertex stays
  // (reflex_left).
  bool reflex_copies = true;
  // The edge boxes whose faces through a close box edge are translated
  // (warp.cpp find_face_shifts, docs/algorithm/tet3d_warp.md "Face
  // translations"), each face by the largest 2^-k (k = 0..4) of its move
  // that keeps its points' side decisions and clearances (warp.cpp
  // fit_face_shifts); empty: none.
  std::span<const EdgeBoxBounds> edge_boxes;
  // Points whose move inverted a tetrahedron once (facet_boxes.cpp, rebuild
  // loop), each with the axes on which it lies on a face of that
  // tetrahedron's box; null: none. Such a point gets its second pass alone
  // from the prewarped point (its first-pass and face moves dropped), without
  // the components along those axes (a face bent by the first pass past an
  // edge-box apex does not freeze the point's move off its facet); when
  // nothing is left or a rule refuses it, it stays (frozen_left). The entry's
  // bits: a for the reporting box's low face along axis a, 3 + a for its high
  // face.
  const std::unordered_map<GridPoint, std::uint8_t, GridPointHash>* second_only = nullptr;
  // With second_only: a component along such an axis that points out of the
  // reporting box is kept (counted in out_of_face); false: dropped (counted
  // in out_of_face_left). mesh_boxes takes the table with them only when its
  // mesh is valid and its worst tetrahedron better
  // (docs/algorithm/tet3d_warp.md "One decision per shared face").
  bool out_of_face = false;
};
// What a table build did per ring point besides its entry: the counts it
// added and its Fig. 4.7 copies, in candidate order. With it a rebuild
// copies the outcome of every point whose inputs are unchanged
// (rewarp_box_vertices) instead of deciding it again.
struct JournalShifts;  // warp.cpp
struct WarpJournal {
  struct Count {
    std::uint32_t point;    // candidate index
    std::uint16_t count;    // index into WarpTable::kCounts
    std::int16_t delta;
  };
  struct Copy {
    std::uint32_t point;  // candidate index
    int facet;
    Vec3 at;
  };
  std::vector<Count> counts;
  std::vector<Copy> copies;
  std::size_t edge_boxes = 0;                  // the build's options.edge_boxes.size()
  std::shared_ptr<const JournalShifts> shifts;  // the build's fitted face translations
};

// `journal` (may be null): receives the build's journal.
WarpTable warp_box_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                            const WarpCandidates& candidates, const WarpOptions& options = {},
                            WarpJournal* journal = nullptr);

// The table warp_box_vertices(candidates, options) makes, made from `old`:
// `old` and `journal` come from a build with the same candidates, reflex
// copies, out_of_face and edge boxes (edge boxes only grow: the same count),
// and `changed` holds every point whose frozen status or second_only entry
// differs between the two builds. The ring points are taken in candidate
// order, as the full build does; a point's decision reads only its own
// options and the entries of its ring neighbours decided before it
// (warp.cpp keeps_decisions, neighbour_ends), so a point outside `changed`
// none of whose neighbours' entries differed keeps its old entry, copies and
// counts; every other point is decided again. Square centres are decided
// again. Same table, same counts as the full build (rewarp_test.cpp).
// `journal` becomes the new table's. Cost: the full build's on the points
// decided again, a lookup per neighbour on the others.
WarpTable rewarp_box_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                              const WarpCandidates& candidates, const WarpOptions& options, const WarpTable& old,
                              const std::unordered_set<GridPoint, GridPointHash>& changed, WarpJournal& journal);

// (leaf, facet) pairs of facet boxes: the candidates are their ring points.
struct FacetLeaf {
  std::int32_t leaf = -1;
  int facet = -1;
};
WarpTable warp_facet_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                              std::span<const FacetLeaf> boxes);

// Euclidean distance from x to facet f (its facet triangles; a construction).
double facet_distance(const Domain3& domain, int facet, Vec3 x);

// The mesh vertex of grid point p: its warped copy if the table has one.
int grid_vertex(const GridPoint& p, const OctTree& tree, const WarpTable* warps, PointBook& book);

}  // namespace pqmesh::tet3d
