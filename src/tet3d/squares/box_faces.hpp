#pragma once
// Box facet triangulation, thesis §4.4 Case A (a box facet that no P face
// crosses), on the smaller box's side.
//
// Subdivision. A face of a leaf b is covered, on the other side, by leaves of
// any sizes. Following §4.4 ("we always triangulate S by considering it a
// facet of b', not b", h(b) >= h(b')), the face is cut into the squares S of
// the finer side: recursively, a square is split into four while its centre
// is a corner of some leaf (a leaf corner in the open square makes
// the leaf across smaller than the square, and then the square's centre is a
// corner of the leaves tiling that smaller cell). The rule does not assume the
// balance condition: protected boxes (§4.1.1) are exempt from it, so two
// leaves meeting at a face may differ by more than a factor two.
//
// Triangulation of one square S: the edges of S are split at every leaf
// corner on them (recursive midpoints: a corner strictly inside an edge of S
// implies a corner at its midpoint, by the same nesting argument), and the
// centre of S is joined to every boundary segment (Case A: "a new point v at
// the centre of the prewarped box facet ... connect v to every segment").
//
// Conformity. The triangulation of S depends only on S and on the global
// CornerSet, never on which side asks, so the two leaves sharing S produce
// the same triangles (with opposite orientation), and two squares sharing an
// edge split it at the same points.
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "pqmesh/vec.hpp"
#include "tet3d/points/first_use_index.hpp"
#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {

// The corners of every leaf (from a builder: all leaves, also those missing
// P; see box_faces.cpp), the points that split box faces and edges.
class CornerSet {
 public:
  // With the builder: also the cell corners of every united vertex box
  // (box_faces.cpp).
  explicit CornerSet(const mv3d::OctreeBuilder& builder);
  // The corners of the given leaves of `tree` (all must be aligned).
  CornerSet(const OctTree& tree, std::span<const std::int32_t> leaves);
  bool contains(const GridPoint& p) const { return index_.find(p) >= 0; }
  std::size_t size() const { return static_cast<std::size_t>(index_.size()); }
  // The deepest level of a leaf with corner p (the smallest box containing
  // p as a vertex, §4.3's h), or -1 if p is no corner.
  std::int32_t finest_level(const GridPoint& p) const {
    const int id = index_.find(p);
    return id < 0 ? -1 : levels_[static_cast<std::size_t>(id)];
  }

 private:
  void add(const GridPoint& p, std::int32_t level);
  // Open addressing (first_use_index.hpp): lookups only, the
  // set is never iterated, so its layout cannot reach the output.
  FirstUseIndex<GridPoint, GridPointHash> index_;
  std::vector<std::int32_t> levels_;  // by id: the deepest level with that corner
};

using GridTriangle = std::array<GridPoint, 3>;

// One square S of a box face (the finer side's square, see above): lower
// corner `lo` (its n coordinate is the face plane), side in fine units, and
// the frame: normal axis n, in-plane axes u = n+1, v = n+2 (mod 3), so that
// (u, v, n) is right-handed; `upper`: the box lies below the plane (its
// outward normal is +n).
struct FaceSquare {
  int n = 0, u = 1, v = 2;
  bool upper = false;
  GridPoint lo;
  std::int64_t side = 0;
  GridPoint centre() const {
    GridPoint c = lo;
    c.f[u] += side / 2;
    c.f[v] += side / 2;
    return c;
  }
};

// The distance of a and b within S's plane (axes u and v only). §4.4's
// choices C1/C2 and D1/D2 ask how far a chord runs from S's centre *within
// S*; the chord lies on the warped square and the centre is prewarped, and
// warping may move a whole face along its normal (two first-pass moves of
// h/8 add up on a face near an edge running across it: every-run seed 36),
// so a 3-D distance would count that move as distance from the centre.
inline double in_square_distance(const FaceSquare& s, Vec3 a, Vec3 b) {
  return std::hypot(axis_coord(a, s.u) - axis_coord(b, s.u), axis_coord(a, s.v) - axis_coord(b, s.v));
}

// The squares of the finer side inside the aligned square `s` (split into
// four while its centre is in `corners`, as above), in a fixed order. Used for
// faces of boxes that are no tree cells (a united vertex box, §4.5.2).
void split_square(const FaceSquare& s, const CornerSet& corners, std::vector<FaceSquare>& out);

// The squares of face (axis, upper) of the aligned box `key`, in a fixed order.
void face_squares(const BoxKey<3>& key, int axis, bool upper, const CornerSet& corners, std::vector<FaceSquare>& out);

// The boundary points of S (its corners and every split point on its sides),
// counter-clockwise seen from +n, starting at S's lower corner.
std::vector<GridPoint> square_ring(const FaceSquare& s, const CornerSet& corners);
// The same into `ring` (cleared first): a loop over squares reuses one buffer.
void square_ring(const FaceSquare& s, const CornerSet& corners, std::vector<GridPoint>& ring);

// Appends the triangles of face (axis, upper) of the aligned box `key`,
// each with its right-hand normal pointing out of the box. Throws
// InternalError for an unaligned (merged) key.
void triangulate_box_face(const BoxKey<3>& key, int axis, bool upper, const CornerSet& corners,
                          std::vector<GridTriangle>& out);

}  // namespace pqmesh::tet3d
