#pragma once
// How the components of P ∩ C meet the surface of the cube C ("rims", thesis
// §4.1.6 last paragraph: "the rims allow us to determine which neighboring
// boxes are adjacent to a given duplicate box"), and adjacency between the
// duplicates of two face-neighbouring boxes (thesis §4.1.1 "Adjacent").
//
// Rule. Two duplicates k of b and k' of b', b's face
// containing (or equal to) the face F of b' on their common plane, are
// adjacent iff their components share a region of POSITIVE AREA of F: a
// point q of F, off every trace of ∂P on F, lying in P ∩ C_b component k and
// in P ∩ C_b' component k'. Consequences, decided exactly:
//   * components touching F only along a curve (a P edge lying in F with
//     both its facets on one side) or at a point (a vertex on F) share no
//     area there: NOT adjacent on that account. (The outward shift of
//     cube_components.hpp keeps such contacts as thin components of the other
//     box; they have no region of F and stay without adjacency through F.)
//   * a facet lying in F covers a region of F that belongs to ∂P, hence to
//     closed P: the component of b holding that facet triangle and the
//     component of b' holding it (one of them the infinitesimally thin
//     component the outward shift keeps on the side away from P) ARE
//     adjacent. This is the only way a thin (touching) component gets an
//     adjacency through F.
//
// Representation (cheap, no planar arrangement): the trapezoidal sampling of
// a face rectangle R. The traces of the facet triangles meeting the cube on
// the plane of R are segments with rational end points (a triangle lying in
// the plane contributes its three sides). Cut R into slabs at the
// u-coordinates of all trace end points and of the points where traces cross
// the sides v = v0, v = v1 of R (traces of distinct triangles meet only at
// their end points or coincide, so inside a slab they are ordered in v); in each slab pick a double u strictly inside;
// on the line at u the traces cross at rational v's, which cut R's v-range
// into intervals; pick a double v strictly inside each. Every region of R
// minus the traces (open, positive area) is a union of such trapezoids, so
// it holds at least one sample, and every sample is off every trace. A
// sample lies inside a triangle lying in the plane (then its component is
// that triangle's), or is off ∂P and is located by components()'s marks (the
// +x ray of the tethers). A region is identified by its sample points; a
// region may hold several samples (one per trapezoid), all with the same
// component. Cost: O(S (s + 1)) exact rational operations for s trace
// segments and S = O(s) slabs, plus one components() call with the samples
// as marks; only done when a caller asks (the octree needs it only for boxes
// with duplicates).
// Not exact in one corner: a slab or interval narrower than the spacing of
// doubles has no double sample point; it is skipped and counted in
// `unresolved` (never seen in the tests; a positive-area region is missed
// only if all of its trapezoids are that thin).
#include <array>
#include <utility>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::mv3d {

// One sample of a region of (face rectangle) ∩ P.
struct RimSample {
  Vec3 point;                   // on the face plane, strictly inside the rectangle, off every trace
  int in_plane_triangle = -1;   // a facet triangle lying in the plane and containing point, or -1
  int component = -1;           // the component of P ∩ C holding point (>= 0: samples outside P are dropped)
};

// Cube face index: axis * 2 + side (side 0: the plane lo[axis]).
struct CubeRims {
  CubeComponents comps;                       // components(domain, cube) (same numbering)
  std::array<std::vector<RimSample>, 6> faces;  // the samples in P of each face
  int unresolved = 0;                         // slabs or intervals without a double sample
  // The faces (bit axis * 2 + side) met by component k in a region of positive area.
  std::vector<int> face_mask() const;
};

CubeRims cube_rims(const Domain3& domain, const Cube& cube);

struct DuplicateAdjacency {
  int axis = -1;                      // the common plane is axis = value
  double value = 0;
  std::vector<std::pair<int, int>> pairs;  // (component of big, component of small), sorted, unique
  std::vector<RimSample> samples_big, samples_small;  // the samples in P, located in each cube
  int unresolved = 0;
};

// big and small are face neighbours: small's face F on the common plane lies
// in big's face (closed cubes touching along F; big may equal small in size).
// Components are numbered as components(domain, big) and
// components(domain, small) number them. Throws std::invalid_argument if the
// cubes are not placed so.
DuplicateAdjacency adjacent_duplicates(const Domain3& domain, const Cube& big, const Cube& small);
// The same with the octree's hints (candidate lists handed down the tree,
// corner 0 status; cube_components.hpp): no step looks at every triangle.
DuplicateAdjacency adjacent_duplicates(const Domain3& domain, const Cube& big, const CubeHint& big_hint, const Cube& small,
                                       const CubeHint& small_hint);
// Either hint may be null (from scratch).
DuplicateAdjacency adjacent_duplicates(const Domain3& domain, const Cube& big, const CubeHint* big_hint, const Cube& small,
                                       const CubeHint* small_hint);

}  // namespace pqmesh::mv3d
