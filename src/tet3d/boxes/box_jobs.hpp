#pragma once
// The box jobs of a finished octree (thesis §4.5): one job per leaf meeting P,
// by its kind (mv3d/leaf_kind.hpp), except the pieces of a united vertex box
// (§4.1.3, vertex_owner = v), which are covered by ONE vertex job for v.
//
//   EmptyInside  -> BoxKind::Empty
//   FacetCone    -> BoxKind::Facet    (apex: the facet)
//   EdgeCone     -> BoxKind::Edge     (apex: the edge, index into Domain3::edges)
//   TwoFacet     -> BoxKind::TwoFacet (apex: the edge of the two facets)
//   vertex_owner = v -> one BoxKind::Vertex job (leaf: the leaf holding v,
//                   apex: v, block: where the united box extends)
// Not meshable, listed in `problems` (the mesh of the other jobs then has a
// hole there): kind Other or Outside-with-component; a VertexCone leaf outside
// every united box; a piece of a united box of another kind than VertexCone
// or EmptyInside; a leaf that a vertex job would mesh besides its own job
// (OctreeBuilder::united_clashes).
// A leaf meeting P inside a united box that is not a piece of it (another
// component of a duplicated cell: the far wall of a narrow slot at its mouth)
// gets its ordinary job by kind; the vertex box meshes cone(v) ∩ B only (its
// facets tested by their sectors at v, square_cases.hpp), so each component
// of every square of B's surface is triangulated by its own boxes.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mv3d/leaf_kind.hpp"
#include "mv3d/octree_builder.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::tet3d {

struct BoxJobs {
  std::vector<BoxJob> jobs;                                // leaves in id order (a vertex job where v's leaf is)
  std::array<std::int64_t, mv3d::kLeafKinds> leaves{};     // leaves per LeafKind
  std::int64_t united_pieces = 0;                          // leaves covered by vertex jobs
  std::vector<std::string> problems;                       // leaves that no job covers, one line each
  std::vector<std::int32_t> problem_leaves;                // their node ids, ascending
};

BoxJobs box_jobs(const mv3d::OctreeBuilder& builder);

// Where v's united box (builder.vertex_box(v), 2x2x2 cells of leaf n's size)
// extends from its cell n: bit a set when it extends one side below n along
// axis a (BoxJob::block).
std::uint8_t united_block(const mv3d::OctreeBuilder& builder, std::int32_t n, int v);

}  // namespace pqmesh::tet3d
