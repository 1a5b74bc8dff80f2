#pragma once
// Vertex smoothing after the collapses, monotone in quality (improve.hpp,
// ../shared/IMPROVEMENT.md "The rule that keeps a guarantee").
//
// Which vertices move (mobility, computed once from the vertex classes):
//   * an interior vertex (no boundary triangle) anywhere;
//   * a vertex inside exactly one facet only when that facet is axis-aligned
//     (all its PLC vertices share one coordinate bit for bit), and then within
//     the facet's plane: that coordinate is kept bit-identical, so the vertex
//     lies exactly on the plane. Its boundary triangles stay on the facet and
//     still tile the same polygon: each is a face of a star tetrahedron whose
//     fourth vertex lies off the plane and does not move, so the tetrahedron's
//     orientation is the triangle's orientation in the plane, and keeping every
//     tetrahedron positive keeps every triangle's orientation around a fixed
//     link polygon;
//   * a vertex on an axis-parallel input edge (its end points share two
//     coordinates bit for bit, and so does the vertex) only along that axis:
//     it stays exactly on the edge's line, so on both facets' planes, and its
//     boundary triangles on either facet keep their orientation as above;
//   * a vertex inside exactly one slanted facet, or on a slanted input edge,
//     to candidates settled onto the facet's plane or the edge
//     (boundary_snap.hpp: within an ulp, the checker's rule); such a move is
//     accepted only if each of the vertex's boundary triangles keeps its
//     orientation, nonzero, in the projection dropping its facet's dominant
//     normal axis (exact orient2d_projected): the triangles around the
//     vertex then still tile the same polygon of each facet;
//   * input vertices never.
// A vertex whose star carries more than one region marker stays.
//
// A move of v to q is accepted only when
//   1. every tetrahedron of the star of v is positively oriented (exact orient3d);
//   2. the star's worst aspect ratio does not increase and is at most aspect_cap;
//   3. the star's minimum dihedral angle increases by at least kMinGain degrees
//      (strict progress: the global minimum dihedral never falls, the global
//      worst aspect ratio never rises, and the passes end);
//   4. every tetrahedron of the star is within the size bound
//      (size_bound.hpp), or was already beyond it before the move and its
//      longest edge does not grow.
// Candidates: the mean of the neighbours (on a facet: of the boundary
// neighbours, projected), halfway and a quarter of the way there, and steps
// along the gradient of the worst star tetrahedron's minimum dihedral angle
// (a construction; it only proposes). The best accepted candidate wins (ties:
// the first in that order).
//
// Order: a pass takes the vertices whose star's minimum dihedral angle is
// below kWorkBelowDihedral, smallest first, ties by id; the first pass of a
// Smoother takes every movable vertex, later passes only the ones whose star
// changed since their last try (collapse_mesh.hpp "Star times"). At its turn
// a vertex is skipped when its star has not changed since its last try (by
// this Smoother or an earlier one: the tries are remembered in a SmoothTries
// the caller keeps across Smoothers) and its mobility is the one it was
// tried with. Neither changes a decision: the outcome of
// a try depends only on the star (its tetrahedra, boundary triangles and
// vertex positions) and the mobility, so an unchanged star is refused again,
// and a move changes the star. (A Smoother fixes the mobility when it is
// made; a boundary flip after that changes a star without changing the
// mobility until the next Smoother.) Deterministic: no decision depends on
// anything but the mesh.
#include <cstdint>
#include <vector>

#include "improve3d/boundary_snap.hpp"
#include "improve3d/collapse_mesh.hpp"
#include "improve3d/size_bound.hpp"
#include "improve3d/vertex_classes.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::improve3d::detail {

// The least gain of the star's minimum dihedral angle a move must bring (degrees).
inline constexpr double kMinDihedralGain = 0.01;
// Smoothing tries only vertices whose star's minimum dihedral angle is below
// this, flips only tetrahedra below it (degrees): the work goes to the worst
// elements, and a pass over a large mesh skips the good majority. Only time
// and quality depend on it (cube of 834k tetrahedra coarsened to 172k: the
// passes after the collapses take 0.5 s at 20, 1.5 s at 25, 3.5 s at 30; the
// small test models reach a few degrees more at 25 than at 20).
inline constexpr double kWorkBelowDihedral = 25;

// Per vertex: code -1 fixed, 0..2 moves within the plane where that coordinate is constant, 3 free,
// 4..6 along the axis code - 4, 7 on the slanted facet `feature`, 8 on the slanted domain edge `feature`.
struct VertexMobility {
  std::vector<std::int8_t> code;
  std::vector<int> feature;
};
VertexMobility vertex_mobility(const Domain3& domain, CollapseMesh& mesh, const VertexClasses& classes);

// Per vertex, the mesh time of its last smoothing try (0: never tried) and
// the mobility code and feature it was tried with, for every Smoother on one
// CollapseMesh.
struct SmoothTries {
  std::vector<std::uint64_t> at;
  std::vector<std::int8_t> code;
  std::vector<int> feature;
};

class Smoother {
 public:
  // mobility: vertex_mobility's, or empty (nothing moves); snap: for the slanted codes (may be
  // null when there are none); tries: kept by the caller across Smoothers of this mesh.
  Smoother(CollapseMesh& mesh, VertexMobility mobility, BoundarySnap* snap, const SizeBound& size, double aspect_cap,
           SmoothTries& tries);

  // One pass (see above); returns the number of vertices moved.
  std::int64_t pass();
  std::int64_t moved_vertices() const { return moved_vertices_; }  // distinct vertices moved so far

 private:
  bool refused_unchanged(int v) const;
  bool try_vertex(int v);
  struct Trial {
    Vec3 q;
    double min_dihedral = 0;
  };
  bool evaluate(int v, Vec3 q, double floor, bool strict, double limit, Trial& trial);
  void measure_star(int v, Vec3 q);
  bool place(int v, Vec3 p, Vec3& q);
  bool fan_keeps_orientation(int v, Vec3 p, Vec3 q);
  bool within_size(int v, Vec3 p, Vec3 q) const;
  double star_min_dihedral(int v);
  Vec3 ascent(int v, int worst_tet, double step) const;

  CollapseMesh& mesh_;
  std::vector<std::int8_t> mobility_;
  std::vector<int> feature_;
  BoundarySnap* snap_;
  const SizeBound& size_;
  double cap_;
  SmoothTries& tries_;
  bool first_pass_ = true;
  std::int64_t moved_vertices_ = 0;
  std::vector<std::uint8_t> moved_;
  std::vector<int> star_, faces_, neighbours_;
  std::vector<int> by_dihedral_;  // star_ by increasing minimum dihedral angle (evaluate's test order)
  std::vector<std::uint64_t> marks_;
  std::uint64_t stamp_ = 0;
  std::vector<double> best_aspect_, best_dihedral_;  // measure_star's
};

}  // namespace pqmesh::improve3d::detail
