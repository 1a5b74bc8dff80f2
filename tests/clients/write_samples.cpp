// pqmesh_write_samples: the writing (and reading) end of the external-client
// tests (tests/clients/CMakeLists.txt).
//   pqmesh_write_samples DIR           writes the sample square (2D) and cube
//                                      (3D) of tests/unit/io_mesh/sample_meshes
//                                      in every format into DIR (.vtu raw,
//                                      zlib and ASCII; .msh 4.1 ASCII and
//                                      binary, 2.2; .mesh; .node)
//   pqmesh_write_samples --read FILE D reads FILE as a 2D (D = 2) or 3D mesh
//                                      and prints "vertices elements boundary"
//                                      and the element markers, one line each
// Exit status 0 on success, 1 with the error message on stderr otherwise.
#include <filesystem>
#include <iostream>
#include <string>

#include "pqmesh/mesh_io.hpp"
#include "sample_meshes.hpp"

namespace {

template <class M>
void write_all(const M& mesh, const std::filesystem::path& dir, const std::string& stem, std::size_t num_cells) {
  using pqmesh::MeshFormat;
  pqmesh::WriteOptions options;
  // A field that differs per element: the element index plus one half.
  pqmesh::CellField field{"quality", {}};
  for (std::size_t i = 0; i < num_cells; ++i) field.values.push_back(static_cast<double>(i) + 0.5);
  // The same values again as Float32 (exact in a float): meshio must read both.
  pqmesh::CellField field32{"quality32", field.values, true};
  options.cell_fields = {field, field32};
  pqmesh::write_mesh(mesh, (dir / (stem + ".vtu")).string(), options);
  options.compress = true;
  pqmesh::write_mesh(mesh, (dir / (stem + "_zlib.vtu")).string(), options);
  options.compress = false;
  options.binary = false;
  pqmesh::write_mesh(mesh, (dir / (stem + "_ascii.vtu")).string(), options);
  pqmesh::write_mesh(mesh, (dir / (stem + ".msh")).string(), options);
  options.format = MeshFormat::Msh22;
  pqmesh::write_mesh(mesh, (dir / (stem + "_22.msh")).string(), options);
  options.format = MeshFormat::Msh41Binary;
  pqmesh::write_mesh(mesh, (dir / (stem + "_41b.msh")).string(), options);
  options.format.reset();
  pqmesh::write_mesh(mesh, (dir / (stem + ".mesh")).string(), options);
  pqmesh::write_mesh(mesh, (dir / (stem + ".node")).string(), options);
}

template <class M>
void print(const M& mesh, std::size_t cells, std::size_t boundary, const std::vector<int>& markers) {
  std::cout << mesh.vertices.size() << ' ' << cells << ' ' << boundary << '\n';
  for (std::size_t i = 0; i < markers.size(); ++i) std::cout << (i ? " " : "") << markers[i];
  std::cout << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 4 && std::string(argv[1]) == "--read") {
      if (std::string(argv[3]) == "2") {
        const pqmesh::TriMesh2 m = pqmesh::read_trimesh(argv[2]);
        print(m, m.triangles.size(), m.edges.size(), m.triangle_markers);
      } else {
        const pqmesh::TetMesh3 m = pqmesh::read_tetmesh(argv[2]);
        print(m, m.tetrahedra.size(), m.faces.size(), m.tetrahedron_markers);
      }
      return 0;
    }
    if (argc != 2) {
      std::cerr << "usage: pqmesh_write_samples DIR | --read FILE 2|3\n";
      return 1;
    }
    const std::filesystem::path dir(argv[1]);
    std::filesystem::create_directories(dir);
    const pqmesh::TriMesh2 square = pqmesh::test::square_mesh(true);
    const pqmesh::TetMesh3 cube = pqmesh::test::cube_mesh(true);
    write_all(square, dir, "square", square.triangles.size());
    write_all(cube, dir, "cube", cube.tetrahedra.size());
    pqmesh::write_mesh(square, (dir / "square.svg").string());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "pqmesh_write_samples: " << e.what() << '\n';
    return 1;
  }
}
