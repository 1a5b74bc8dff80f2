#pragma once
// Collapses that remove the worst tetrahedra (Klingner and Shewchuk,
// "Aggressive tetrahedral mesh improvement", 2007: edge contraction as an
// improvement operation), after smoothing and flips (improve.hpp).
//
// A pass visits the live tetrahedra whose minimum dihedral angle is below
// kWorkBelowDihedral (smooth.hpp), smallest first, ties by id
// (worst_first.hpp); for each still alive it tries its six edges in the order
// (0 1) (0 2) (0 3) (1 2) (1 3) (2 3), each as the coarsening passes do (the
// end of the lower vertex class deleted first, ties: the smaller id; then the
// other way), and stops at the first collapse done.
// The collapser given is built with QualityLimits::min_dihedral = 180, so a
// collapse is accepted by every rule of improve.hpp and, where the old region
// (the tetrahedra of u and v) is within target_aspect, only when no new
// tetrahedron's minimum dihedral angle is below the old region's least. The
// tetrahedron visited holds u and v, so it vanishes: a collapse replaces it
// and its region by tetrahedra no worse in minimum dihedral angle, within
// the aspect rule and the cap, and removes a vertex (so the passes end).
// Cost per tetrahedron visited: at most twelve collapse checks.
#include <cstdint>
#include <vector>

#include "improve3d/collapse_check.hpp"
#include "improve3d/collapse_mesh.hpp"
#include "improve3d/vertex_classes.hpp"

namespace pqmesh::improve3d::detail {

class ImprovingCollapses {
 public:
  ImprovingCollapses(CollapseMesh& mesh, const VertexClasses& classes, Collapser& collapser)
      : mesh_(mesh), classes_(classes), collapser_(collapser) {}

  // One pass; returns the number of collapses.
  std::int64_t pass();

 private:
  bool collapse_tet(int t);
  bool collapse_edge(int a, int b);

  CollapseMesh& mesh_;
  const VertexClasses& classes_;
  Collapser& collapser_;
};

}  // namespace pqmesh::improve3d::detail
