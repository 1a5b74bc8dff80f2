#pragma once
// Case B of §4.4 after the first warping pass (beyond the thesis;
// docs/algorithm/tet3d_warp.md "The Case B vertex on the warped square"). The
// thesis puts the I vertex of a P edge E and a box face square S on the
// PREWARPED square. Where E passes within h/8 of a box edge e of two faces S1,
// S2 of one box (E clipping the box near e), its two crossings x1 (on S1) and
// x2 (on S2) are both close to e and to each other, whatever the first pass
// does to e: Lemma 6 ("no two I vertices closer than min(t, h/16)") fails for
// them, and every tetrahedron on the chain x1 - apex - x2 of that edge box is a
// sliver (schoenhardt, aspect 2,467). The first pass moves e away from E by
// h/8, so S1 and S2 tilt away from E; E crosses the tilted squares farther
// apart. This is that crossing: E meets the mean plane of S's warped corners
// (through their mean, normal the bilinear patch's at its centre), rounded
// within an ulp of E.
#include <optional>

#include "pqmesh/vec.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/warp/warp_table.hpp"

namespace pqmesh::tet3d {

// E = segment [a, b]. Empty when no corner of S is warped, when E is
// parallel to the mean plane, or when the crossing leaves the open segment
// or S's prewarped extent in its two in-plane axes (then the caller keeps
// the prewarped crossing). A construction: whether it is used is decided on
// doubles (as every warping threshold, docs/algorithm/tet3d_boxes.md
// "Exactness"); every exact
// decision of Case B stays on the prewarped square.
std::optional<Vec3> warped_square_crossing(Vec3 a, Vec3 b, const FaceSquare& s, const OctTree& tree,
                                           const WarpTable* warps);

}  // namespace pqmesh::tet3d
