#pragma once
// Tetrahedra of empty boxes (§4.5.1) and of facet boxes (§4.5.4), before
// warping (§4.3 not done: a box corner may lie on F; it is then its own
// crossing point, cut_square.hpp).
//
// A facet box b holds one P facet F and no P vertex or edge in P ∧ b, so
// P ∧ b = cube ∩ (P's side of F's plane), convex. Its faces are triangulated
// square by square (Case A or C, cut_square.hpp). The central vertex v is the
// box centre; with d its signed distance to F (a construction; thresholds in
// floating point, either outcome valid):
//   d <= -h/4  v inside P: v coned to the face triangles and to the fan of
//              F ∩ b from its central point g (the mean of the polygon's
//              vertices, rounded onto F);
//   |d| < h/4  v moved onto F (rounded onto F): coned to the face triangles;
//   d >= h/4   v beyond F: every cone v-T is clipped by F into a prism with
//              bottom T and top T' on F (a vertex of T on F is its own clip),
//              cut into 1, 2 or 3 tetrahedra. Each quadrilateral side of a
//              prism is shared with the next prism of the same box and is cut
//              by the diagonal from its smallest vertex key; diagonals from
//              one total order never form the cyclic pattern of a Schönhardt
//              prism, so the three tetrahedra always exist (the prism's
//              smallest vertex sees both quads through it by diagonals).
// Every tetrahedron (cones, the F ∩ b fan, prism pieces) is written in the
// vertex order that the construction makes positive (facet_boxes.cpp states
// why for each); exact orient3d on the final (rounded or warped) coordinates
// must agree, else InternalError naming the leaf. Nothing is flipped.
#include <cstdint>
#include <span>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "tet3d/box_faces.hpp"
#include "tet3d/vertex_key.hpp"

namespace pqmesh::tet3d {

struct BoxJob {
  std::int32_t leaf = -1;
  int facet = -1;  // -1: an empty box
};

struct FacetBoxStats {
  std::int64_t empty = 0, inside = 0, on_facet = 0, beyond = 0;  // boxes per case
};

struct BoxMeshOptions {
  bool warp = false;  // §4.3 second pass for the facet boxes (warp.hpp)
};

struct BoxMesh {
  TetMesh3 mesh;                        // region attribute 0; no boundary face list
  std::vector<VertexKey> keys;          // per vertex
  std::vector<std::int32_t> tet_leaf;   // per tetrahedron
  FacetBoxStats stats;
  std::int64_t warped = 0, warp_conflicts = 0;
};

BoxMesh mesh_boxes(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                   std::span<const BoxJob> jobs, const BoxMeshOptions& options = {});

}  // namespace pqmesh::tet3d
