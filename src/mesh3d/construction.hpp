#pragma once
// One construction of the 3D pipeline (docs/algorithm/mesh3d.md): octree with
// the separating splits asked for, box plan, box tetrahedra, boundary
// triangles with facet markers, region attribute, and the aspect review that
// tet_mesh's choice of octree reads (TetSeparation, pqmesh/tetmesh.hpp).
#include <chrono>
#include <string>
#include <vector>

#include "mesh3d/aspect_review.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/tetmesh.hpp"

namespace pqmesh::mesh3d {

// Which octree a construction builds: the extended boxes' margin in box
// sides (mv3d::OctreeOptions::extended_margin; the thesis's 2, or 1) and the
// separating splits (§4.1.7 steps 6 and 9): none (separate false), those of
// the leaves holding a face of `faces`, or, with `faces` empty, every edge and
// facet box's. grid_shift: the generic grid's offset number
// (mv3d::OctreeOptions::grid_shift). thesis(): margin 2 and every separating
// split.
struct OctreeVariant {
  int extended_margin = 2;
  bool separate = false;
  FaceFlags faces;
  int grid_shift = 0;
  bool thesis() const { return extended_margin == 2 && separate && faces.edges.empty() && faces.facets.empty(); }
};

struct Construction {
  TetMeshResult result;  // stats: every field but light_rejected / seconds_light
  AspectReview review;
  std::vector<int> face_facets;  // Domain3 facet id of each boundary triangle of result.mesh
  // Not empty when some leaves have no box job (tet3d::box_jobs problems) and
  // the octree is lighter than the thesis's: the first problem; result is then
  // empty and review.over_bound holds flag_leaf_faces of every such leaf
  // (with add_edges_of_facets). On
  // the thesis's octree MeshNotSupported is thrown instead.
  std::string unsupported;
  // Not empty when review_stuck_corners dropped the construction before its
  // box stage (construct's review_stuck): why; result is then empty.
  std::string stuck;
};

// alpha: the domain's (radians), for the review. t0: the start of tet_mesh,
// for options.progress. review_stuck: with warping, the box stage stops
// after its first warp table when review_stuck_corners drops the
// construction (`stuck` says why; result is then empty). Throws InvalidInput
// for a bad size field or max_size, MeshNotSupported (above), InternalError
// when an invariant breaks.
Construction construct(const Domain3& domain, const TetMeshOptions& options, const OctreeVariant& variant,
                       double alpha, std::chrono::steady_clock::time_point t0, bool review_stuck = false);

}  // namespace pqmesh::mesh3d
