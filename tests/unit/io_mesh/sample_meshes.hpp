#pragma once
// Small meshes built by hand for the mesh I/O tests, and a scratch directory.
#include <filesystem>
#include <string>

#include "pqmesh/mesh.hpp"

namespace pqmesh::test {

// The square [0.1, 0.1 + 1/3]^2 (coordinates chosen so that their decimal
// forms are long: an exact round trip needs all 17 digits), split by the
// diagonal v0-v2 into two counter-clockwise triangles (0,1,2) and (0,2,3).
// Markers: triangles {7, -2}, the four sides 1..4, vertices {1, 0, 3, -4}.
TriMesh2 square_mesh(bool with_markers);

// The cube [0,1]^3 scaled by 0.1 and shifted by 1/3, split into the 6
// Freudenthal tetrahedra around the diagonal v0-v7 (vertex i + 2j + 4k is
// corner (i, j, k)); the 12 boundary triangles oriented outward.
// Markers: tetrahedra {1, 2, 3, 0, -5, 2}, faces 1..6 by cube side,
// vertices i % 3.
TetMesh3 cube_mesh(bool with_markers);

// A fresh empty directory under the system temp directory.
std::filesystem::path scratch_dir(const std::string& name);

}  // namespace pqmesh::test
