#pragma once
// Output meshes: flat arrays of indices plus markers (docs/DESIGN_RULES.md
// "Data layout and speed").
//
// Orientation convention (checked by the validity checker):
//   TriMesh2: every triangle (a, b, c) is counter-clockwise, orient2d(a,b,c) > 0.
//   TetMesh3: every tetrahedron (a, b, c, d) has positive volume,
//             det(b-a, c-a, d-a) > 0, i.e. d lies on the side of triangle abc
//             that its right-hand normal points to (the VTK/Gmsh convention).
// Boundary faces (edges in 2D, triangles in 3D) are listed with their markers;
// a boundary triangle (a, b, c) has its right-hand normal pointing out of the mesh.
#include <array>
#include <vector>

#include "pqmesh/vec.hpp"

namespace pqmesh {

struct TriMesh2 {
  std::vector<Vec2> vertices;
  std::vector<int> vertex_markers;              // empty or one per vertex
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_markers;            // region attribute; empty or one per triangle
  std::vector<std::array<int, 2>> edges;        // boundary / input segments
  std::vector<int> edge_markers;                // empty or one per edge
};

struct TetMesh3 {
  std::vector<Vec3> vertices;
  std::vector<int> vertex_markers;              // empty or one per vertex
  std::vector<std::array<int, 4>> tetrahedra;
  std::vector<int> tetrahedron_markers;         // region attribute; empty or one per tetrahedron
  std::vector<std::array<int, 3>> faces;        // boundary triangles
  std::vector<int> face_markers;                // input facet marker; empty or one per face
};

}  // namespace pqmesh
