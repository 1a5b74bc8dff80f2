#pragma once
// The aspect review of a construction (docs/algorithm/mesh3d.md "Light
// construction first"): the worst aspect ratio of the mesh and the P faces
// near its tetrahedra above the bound C / alpha, which the next construction
// separates.
#include <cstdint>
#include <string>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "pqmesh/mesh.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::mesh3d {

// A set of P edges and facets: one flag per Domain3 edge / facet id.
struct FaceFlags {
  std::vector<char> edges, facets;
  std::int64_t count() const;
  // Sets every flag set in `more` (same sizes); true when one was not set yet.
  bool merge(const FaceFlags& more);
  // Flags every edge of a flagged facet: a protected leaf holding facets of
  // an edge outside it (a leaf of no thesis kind) is split only by the edge
  // separation of §4.1.7 step 6, which comes before edge protection. O(edges).
  void add_edges_of_facets(const Domain3& domain);
};

// Every flag clear, sized for the domain's edges and facets.
FaceFlags no_faces(const Domain3& domain);

// Flags the edges and facets of leaf's component, and every edge at a vertex
// that component holds with its two facets. Cost O(edges) per such vertex.
void flag_leaf_faces(const mv3d::OctreeBuilder& builder, std::int32_t leaf, FaceFlags& out);

struct AspectReview {
  double max_aspect = 0;  // NaN or infinity for a degenerate tetrahedron
  double min_dihedral = 180, max_dihedral = 0;  // degrees
  // flag_leaf_faces of the leaf of each tetrahedron with
  // aspect * alpha > kMeasuredAspectAlphaC.
  FaceFlags over_bound;
};

// tet_leaf: the leaf (node id of builder's tree) of every tetrahedron of mesh.
// Cost: one aspect ratio per tetrahedron through TetrahedronQualityMemo (the
// octree's tetrahedra are a few thousand shapes repeated), O(edges) per vertex
// held by a leaf above the bound.
AspectReview review_aspect(const mv3d::OctreeBuilder& builder, const std::vector<std::int32_t>& tet_leaf,
                           const TetMesh3& mesh, double alpha);

// The review of a lightest construction before its box stage
// (docs/algorithm/mesh3d.md "Light construction first"): `stuck` holds the
// tetrahedra at the first warp table's stuck corners
// (tet3d/rebuild/stuck_corners.hpp). Empty when every one of them has
// aspect * alpha <= kMeasuredAspectAlphaC (the test review_aspect's caller
// applies to the whole mesh); else why the construction is dropped. Cost: one
// aspect ratio per tetrahedron.
std::string review_stuck_corners(const tet3d::BoxMesh& stuck, double alpha);

}  // namespace pqmesh::mesh3d
