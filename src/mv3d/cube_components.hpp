#pragma once
// Connected components of P ∩ C for an axis-aligned closed box C and a
// validated polyhedral domain P (thesis §4.1.1 "Duplicate", §4.1.6 "The
// duplication process"): an octree box whose cube meets P in several
// components is duplicated, one box per component, and each duplicate
// contains the P faces incident on its component.
//
// Degenerate positions: ONE symbolic perturbation, the outward shift. C is
// replaced by the slightly larger box
//     C_e = [xlo - e, xhi + e] x [ylo - e^2, yhi + e^2] x [zlo - e^3, zhi + e^3],
// e > 0 infinitesimal (the 3D form of the quad2d rule, components2d.hpp).
// Every decision is the exact sign of a polynomial in e and in the probe
// offset d << e^3 of cube_components.cpp (detail::Pert, first non-zero
// coefficient), so:
//   * a P vertex on a plane of C is inside C; a P edge or facet lying on a
//     plane of C is inside C; P faces touching C from outside count as
//     meeting it (they meet the closed cube);
//   * no P vertex lies on ∂C_e, no P edge (nor facet-triangle side) meets an
//     edge of C_e, no facet plane passes through a corner of C_e: ∂P crosses
//     ∂C_e transversally;
//   * the components are those of P ∩ C for the CLOSED cube (the argument of
//     components2d.hpp carries over verbatim: C lies in the interior of C_e,
//     and distinct components of P ∩ C are at positive distance). A component
//     may be infinitesimally thin, e.g. P touching C from outside along a
//     facet lying on a plane of C; it is reported like any other.
//
// Method (documented in cube_components.cpp): sheets (components of ∂P ∩ C) by
// union-find of facet triangles whose pieces in C share a vertex or a side (a
// triangle meets the convex C_e in a convex, hence connected, piece); regions
// of ∂C ∩ P joined to the sheets by walking axis-parallel lines on ∂C (the 12
// cube edges and probe lines through every point where a triangle side crosses
// a cube face); internal floaters joined by the tether of §4.1.6 (a ray in +x
// from the shell's largest vertex). Fast path: when the facets meeting C form
// one cone whose apex meets C (they share a vertex v lying in C; or they are
// the two facets of the one P edge meeting C; or there is one facet and no
// edge), P ∩ C is connected (cube_components.cpp, single_cone).
#include <span>
#include <utility>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::mv3d {

// The closed box [lo, hi] (lo < hi in every coordinate). Octree cubes have
// dyadic coordinates, so hi = lo + side is exact for them.
struct Cube {
  Vec3 lo, hi;
};

inline Cube cube_of(Vec3 lo, double side) { return {lo, {lo.x + side, lo.y + side, lo.z + side}}; }

// The P faces incident on one component of P ∩ C (closed, after the shift).
// All ids are sorted and unique.
struct ComponentFaces3 {
  std::vector<int> vertices;   // P vertices lying in C (each in exactly one component)
  std::vector<int> edges;      // indices into Domain3::edges of P edges meeting the component
  std::vector<int> facets;     // facet ids meeting the component (a non-convex facet may meet several)
  bool whole_cube = false;     // C ⊂ P: no P face meets C
};

struct CubeComponents {
  Cube cube;
  std::vector<ComponentFaces3> components;
  // (facet triangle index, component) for every facet triangle meeting C,
  // sorted by triangle: each triangle meets C in one convex piece, so it
  // belongs to exactly one component.
  std::vector<std::pair<int, int>> triangle_component;
  bool fast_path = false;      // decided by the common-vertex rule
  // For each marked point (see components()), its component or -1 if it lies
  // outside P.
  std::vector<int> mark_component;
};

// Facet triangles (indices into Domain3::facet_triangles) meeting the closed
// (shifted) box, sorted.
std::vector<int> triangles_meeting(const Domain3& domain, const Cube& cube);
// The same, restricted to candidates (e.g. the parent box's list). Triangles
// of `known` (sorted, a subset of candidates) are known to meet the box, e.g.
// those meeting a box inside it, and are not tested again.
std::vector<int> triangles_meeting(const Domain3& domain, const Cube& cube, std::span<const int> candidates,
                                   std::span<const int> known = {});

// What a caller that already knows the neighbourhood of C hands down
// (candidate lists passed down the tree, valid since ex(child) ⊂
// ex(parent)), so that no step looks at every facet triangle.
struct CubeHint {
  std::span<const int> candidates;  // every facet triangle meeting C_e is among them
  bool candidates_exact = false;    // they are exactly those triangles, sorted
  bool corner0_in = false;          // corner 0 of C_e, lo - (e, e^2, e^3), lies in P
};

// Is corner 0 of C_e in P? By parity along x from -infinity over every
// facet triangle: O(T), for roots and tests.
bool corner0_in(const Domain3& domain, const Cube& cube);
// The same for `inner` ⊂ `outer` (closed boxes), from outer's corner 0 by an
// axis-parallel walk inside outer's C_e; outer_tris must hold every facet
// triangle meeting outer's C_e. Cost O(|outer_tris|).
bool corner0_in_from(const Domain3& domain, const Cube& inner, const Cube& outer, bool outer_corner0_in,
                     std::span<const int> outer_tris);
// The same between any two boxes `from`, `to` (corner 0 of from's C_e known
// to be in P or not): the walk goes from corner to corner along x, y, z, so it
// stays in any box holding both corners; `tris` must hold every facet
// triangle meeting such a box's C_e (e.g. two children of one parent, with the
// parent's list). Cost O(|tris|) per coordinate that differs.
bool corner0_in_walk(const Domain3& domain, const Cube& to, const Cube& from, bool from_corner0_in,
                     std::span<const int> tris);

// Bounds on the faces of the component of P ∩ C holding facet triangle t,
// without the walks of components() (steps 1-3 and the face lists only):
// `all` lists the faces of every facet triangle meeting C (a superset of any
// component's faces), `sheet` those of the sheet holding t, the component of
// ∂P ∩ C that t's piece lies in (a subset of t's component's faces: a
// component is a union of sheets). Faces as in ComponentFaces3 (vertices in
// C, P edges meeting C, facets). A test that some face "interferes" is then
// decided without components() when `all` has none or `sheet` has one.
// tris: exactly the facet triangles meeting C_e, sorted; t among them.
struct FaceBounds {
  ComponentFaces3 all, sheet;
};
FaceBounds face_bounds(const Domain3& domain, const Cube& cube, std::span<const int> tris, int t);

// Components of P ∩ C. Cost: O(c) to select the m triangles meeting C among
// the c candidates, then, off the fast path, O(m k) for the k probe lines
// (k <= 6 x the triangle sides meeting C); the corners are located by walking
// the cube edges from corner 0 (status given). The exact arithmetic (GMP
// rationals) runs only where double filters cannot decide.
// allow_fast_path = false forces the full computation (tests compare both).
// marks: points of the closed cube, none on ∂P; each is located in the
// components (mark_component) by the ray of the tethers (a ray in +x to the
// first triangle crossed, or to its exit point on ∂C), e.g. the centre of a
// box inside ex(b) for P ∧ ex(b) when no P face meets the box; on the fast
// path by a walk from corner 0.
CubeComponents components(const Domain3& domain, const Cube& cube, const CubeHint& hint, bool allow_fast_path = true,
                          std::span<const Vec3> marks = {});
// The same from scratch (candidates: all T triangles; corner 0 by corner0_in).
CubeComponents components(const Domain3& domain, const Cube& cube, bool allow_fast_path = true,
                          std::span<const Vec3> marks = {});

}  // namespace pqmesh::mv3d
