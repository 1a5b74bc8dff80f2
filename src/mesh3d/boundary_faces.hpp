#pragma once
// The boundary triangles of a box mesh and the input facet each lies on, so
// that the input facet markers are carried to the boundary triangles.
//
// Boundary triangles are the faces of exactly one tetrahedron, written as the
// outward face of that tetrahedron (right-hand normal out of the mesh,
// pqmesh/mesh.hpp), in the order (tetrahedron, face) of the mesh.
//
// Facet of a boundary triangle T of tetrahedron t in leaf b: the facets of
// b's component (NodeData3::facets) are tried first, then the owners of the
// facet triangles meeting b's closed cube (NodeData3::cube_tris: a flush leaf
// whose upper face lies on a facet does not list that facet in its component,
// the outward perturbation of cube_components.hpp keeping it outside the
// shifted cube). T lies on facet F when all three vertices pass
// within_ulp_of_plane for F's plane (the checker's rule,
// docs/algorithm/quality.md "The validity checker"). Several coplanar facets
// can pass; then the one whose facet triangles contain T's centroid, projected
// along the dominant axis of the plane and decided by exact orient2d_projected
// on the (rounded) centroid, is taken. A boundary triangle on no facet of its
// leaf throws InternalError naming it.
#include <cstdint>
#include <span>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "pqmesh/mesh.hpp"

namespace pqmesh::mesh3d {

// Fills mesh.faces and mesh.face_markers (Facet3::marker of the facet found);
// returns the facet id of every boundary triangle.
std::vector<int> add_boundary_faces(const mv3d::OctreeBuilder& builder, std::span<const std::int32_t> tet_leaf,
                                    TetMesh3& mesh);

}  // namespace pqmesh::mesh3d
