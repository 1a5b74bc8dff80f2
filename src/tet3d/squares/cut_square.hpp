#pragma once
// Thesis §4.4 Case C on one square S of a box face (box_faces.hpp): a single
// P facet F crosses S and π = S ∩ (P's side of F) is triangulated. Before
// warping (§4.3, not yet done) a square corner may lie exactly on F; such a
// corner is its own crossing (an exact grid point on F).
//
// Classification of S's ring (corners and split points, exact orient3d):
//   no ring point on P's side            -> nothing (π is empty or lies in ∂S);
//   no ring point beyond F               -> Case A: centre joined to the ring;
//   otherwise (F crosses S's interior)   -> the ring points on P's side, the
//     crossings x, y of F with the two ring segments that change side (or the
//     ring points on F), and the chord x-y bound the convex polygon π;
//     C1: m = midpoint of x, y within h/4 of the square centre c (a
//         constructed distance, a floating-point threshold as in
//         docs/algorithm/quad2d.md "Mesh vertices and warping": either
//         outcome is valid) -> m joined to every side of π except the two
//         chord halves;
//     C2: otherwise. c on P's side: c joined to every side of π (chord
//         included). c beyond F: each side p q of π's walk from y to x with
//         the segments c-p, c-q clipped at the chord gives a quadrilateral
//         p q q' p' (a triangle when p or q is on F), cut by the diagonal from
//         its smallest vertex key. c on F: as C1 with c for m.
// Every constructed point is keyed by the square, F and the ring points it
// comes from, and rounded onto F (facet_plane.hpp) without leaving S's plane.
// The result depends only on (S, F, corner set), so the two boxes sharing S
// build the same triangles.
#include <array>
#include <vector>

#include "tet3d/squares/box_faces.hpp"
#include "tet3d/points/facet_plane.hpp"
#include "tet3d/points/point_book.hpp"
#include "tet3d/warp/warp.hpp"

namespace pqmesh::tet3d {

enum class CutCase : std::uint8_t { Empty, Whole, C1, C2Inside, C2Outside, C2On };

// Appends π's triangles as PointBook ids, each with its right-hand normal
// along +n (S.n); returns the case taken.
// Ring points are resolved through `warps` (may be null): a warped ring point
// takes part with its moved coordinates (§4.3; the square is then no longer
// planar, and its crossings lie between the moved points).
CutCase triangulate_cut_square(const FaceSquare& s, const CornerSet& corners, const OctTree& tree,
                               const FacetPlane& plane, PointBook& book, std::vector<std::array<int, 3>>& out,
                               const WarpTable* warps = nullptr);

// The in-plane axis of S along which a point of S is moved (settled) onto the
// plane's: the one where the plane's normal has the larger component (a plane
// crossing S is not parallel to S's plane, so that component is nonzero).
int settle_axis(const FaceSquare& s, const FacetPlane& plane);

}  // namespace pqmesh::tet3d
