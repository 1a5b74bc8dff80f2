#pragma once
// Helpers of the improve3d tests: the facet of every boundary triangle (which
// tet_mesh does not return), and one coarsening run with its checks.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "improve3d/improve.hpp"
#include "mesh/check3d_plane.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/mesh.hpp"
#include "predicates/predicates.hpp"

namespace pqmesh::test {

// The facet each boundary triangle lies on, by the checker's rule (all three
// vertices within an ulp of the facet's plane, exact), among the facets with
// the triangle's marker; among coplanar candidates the one whose facet
// triangles hold the centroid (exact orient2d_projected on the rounded
// centroid), as src/mesh3d/boundary_faces.cpp decides. -1 when none fits.
std::vector<int> facets_of_faces(const Domain3& domain, const TetMesh3& mesh);

// The construction's own mesh: tet_mesh's coarsening (when its options have
// it) turned off, so the tests here start from the unimproved mesh.
template <class Options>
Options construction_only(Options options) {
  if constexpr (requires { options.improve; }) options.improve = false;
  return options;
}

// Quality figures of a mesh for the reports.
struct MeshFigures {
  std::int64_t tetrahedra = 0;
  double worst_aspect = 0, min_dihedral = 0, longest_edge = 0;
};
MeshFigures figures(const TetMesh3& mesh);

// Total boundary area per face marker, sorted by marker.
std::vector<std::pair<int, double>> area_per_marker(const TetMesh3& mesh);

// The star of vertex 6 at u in the octahedron with corners first, (-1, 0, 0),
// (0, +-1, 0), (0, 0, +-1): eight tetrahedra (one per octant), each oriented
// positive when it can be (exact orient3d), no boundary triangles.
TetMesh3 octahedron_star(Vec3 first, Vec3 u);

}  // namespace pqmesh::test
