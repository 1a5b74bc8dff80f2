// Mesh the unit cube with the pqmesh library, check the mesh, write it as .vtu.
#include <iostream>
#include <vector>

#include "pqmesh/check.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/tetmesh.hpp"

int main(int argc, char** argv) {
  pqmesh::Plc3 cube;  // 8 corners and 6 square facets with markers 1..6
  cube.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<std::vector<int>> squares = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (int f = 0; f < 6; ++f) cube.facets.push_back({.loops = {squares[f]}, .marker = f + 1});
  try {
    const pqmesh::Domain3 domain = pqmesh::make_domain(cube);  // validates and orients
    pqmesh::TetMeshOptions options;
    options.max_size = 0.25;
    const pqmesh::TetMeshResult result = pqmesh::tet_mesh(domain, options);
    const pqmesh::CheckReport report = pqmesh::check_mesh(result.mesh, domain);
    std::cout << report.to_text() << '\n';
    if (!report.valid()) return 1;
    pqmesh::write_mesh(result.mesh, argc > 1 ? argv[1] : "cube.vtu");
  } catch (const pqmesh::Error& e) {  // bad input: the message names the ids
    std::cerr << e.what() << '\n';
    return 2;
  }
}
