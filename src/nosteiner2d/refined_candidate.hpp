#pragma once
// A candidate triangulation without boundary Steiner points beyond the thesis
// (docs/algorithm/nosteiner2d.md "Refined candidates"): Delaunay refinement of
// the constrained Delaunay triangulation of P in which no constrained edge is
// ever split (cdt2d::refine_constrained_delaunay with
// RefineOptions::split_constraints = false, src/cdt2d/refine.hpp "Without
// constraint splits"; Triangle's -Y). Every new point lies strictly inside P,
// so dP stays split exactly at the input vertices.
#include <cstddef>
#include <vector>

#include "improve2d/quality_pass.hpp"

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"

namespace pqmesh::detail {

struct RefinedCandidate {
  // Input vertices first (ids preserved), then the inserted points in
  // insertion order; triangles counter-clockwise, triangle_markers =
  // kRegionRefined; no edges.
  TriMesh2 mesh;
  double target_degrees = 0;
  std::size_t inserted = 0;     // interior points: the seeds, then the refinement's points
  std::size_t seeds = 0;        // of which seeds (seed_points.hpp), right after the input vertices
  bool target_reached = false;  // every triangle not excused (a sharp input corner) meets the target
  bool cap_reached = false;     // stopped by the point cap
  std::size_t given_up_outside = 0, given_up_near = 0, given_up_flat = 0, apex_points = 0;  // cdt2d::RefineResult's counts
};

// The point cap of one refinement: 32 n + 4096 for n input vertices. It
// bounds the work (each insertion is expected O(1) amortised besides the
// walk); refinement towards a reachable target on the test inputs stays far
// below it (docs/MEASUREMENTS.md "No boundary Steiner points").
std::size_t refined_point_cap(const Domain2& domain);

// Refines the CDT of `domain` and the points `seeds` (distinct, strictly
// inside P; seed_points.hpp) towards `target_degrees` (> 0) with at most
// `max_new_points` (> 0) further interior points. Cost: the CDT
// (O(n log n)) plus the refinement loop, linear in the points inserted apart
// from the walks and cavities (local on graded meshes).
RefinedCandidate refined_candidate(const Domain2& domain, double target_degrees, std::size_t max_new_points,
                                   const std::vector<Vec2>& seeds = {});

// The quality-pass settings tried on each refined candidate, in this order
// (each on a copy of the candidate; the caller keeps the first maximum):
//   0: the default pass (it also removes the Steiner vertices it can);
//   1: no vertex removed (flips and moves only): the refinement's points stay;
//   2: as 1, with two rounds of smoothing sweeps and two final sweeps over the
//      vertices whose star's smallest angle is below the target.
// The default pass coarsens greedily against the mesh's current smallest
// angle, which can undo the refinement where it was needed (measured:
// docs/MEASUREMENTS.md "No boundary Steiner points").
std::vector<QualityPassOptions> refined_pass_variants(double target_degrees);

}  // namespace pqmesh::detail
