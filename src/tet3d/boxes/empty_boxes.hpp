#pragma once
// Tetrahedra of empty boxes (thesis §4.5.1) and their assembly into one mesh,
// the first stage of the 3D mesher.
//
// An empty box is a leaf whose closed cube lies in P with no P face crossing
// its interior. Each is cut into tetrahedra by joining its centre (the
// prewarped centroid, §4.5.1) to the triangles of its six faces
// (box_faces.hpp), or, when all six faces are Kuhn faces (shared with an
// empty box of its size, no split point, no warped corner: empty_box.cpp),
// into the six Kuhn tetrahedra of its main diagonal. Since the face
// triangulations agree from both sides, the tetrahedra of all empty boxes
// meet face to face.
//
// Vertices are identified by their GridPoint (box corner, face centre, box
// centre; a VertexKey of kind Grid), never by coordinates; vertex ids are
// assigned in order of first use while leaves are visited in the given
// order, faces in the order (axis 0..2) x (lower, upper) and triangles in
// ring order, so the output is a deterministic function of the octree and the leaf list.
#include <cstdint>
#include <span>
#include <vector>

#include "mv3d/octree_builder.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/facet_boxes.hpp"
#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {

// Leaf n meets P in the whole cube and no P face meets its closed cube
// (NodeData3: has_component && rep_triangle == -1).
bool is_empty_inside(const mv3d::OctreeBuilder& builder, std::int32_t n);

// Every facet triangle meeting leaf n's closed cube lies in a closed
// half-space bounded by one of the cube's planes and missing the open cube
// (exact comparisons of input coordinates with the dyadic box planes).
bool facets_on_cube_boundary_only(const mv3d::OctreeBuilder& builder, std::int32_t n);

// Leaf n's open cube lies in P and every P facet triangle meeting its closed
// cube lies in a closed half-space bounded by one of the cube's planes and
// missing the open cube (so P faces touch the cube only on its boundary, e.g.
// a facet of a grid-aligned domain lying on a box plane). Includes the empty
// inside leaves. Decided exactly: coordinate comparisons with the dyadic box
// planes, and locate() of the cube centre for leaves touching a facet.
bool is_flush_inside(const mv3d::OctreeBuilder& builder, std::int32_t n);

// Leaves (from leaves_by_id(), so in id order) satisfying is_flush_inside
// (flush = true) or is_empty_inside (flush = false).
std::vector<std::int32_t> empty_leaves(const mv3d::OctreeBuilder& builder, bool flush);

// Tetrahedralizes the given leaves as empty boxes: mesh_boxes
// (facet_boxes.hpp) with every job an empty box, so the vertex keys are all
// VertexKind::Grid. With a builder, leaves that are flush but not
// is_empty_inside keep every face's square fans (no Kuhn faces); on a bare
// tree every leaf is an empty box. Each leaf must be an aligned leaf; the caller
// is responsible for them being empty in the sense above. Face splits use the
// corners of every leaf meeting P (box_faces.hpp CornerSet).
BoxMesh mesh_empty_boxes(const mv3d::OctreeBuilder& builder, std::span<const std::int32_t> leaves);
// The same on a bare tree with an explicit corner set (tests, and callers that
// mesh a tree without a domain).
BoxMesh mesh_empty_boxes(const OctTree& tree, const CornerSet& corners, std::span<const std::int32_t> leaves);

}  // namespace pqmesh::tet3d
