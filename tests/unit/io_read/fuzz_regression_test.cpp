// Regression tests for inputs found by mutation fuzzing of the readers. Each
// input is the minimised file; the promise under test is "bad input gets a
// ParseError, never a crash": before the fix each of these announced ~2^31
// vertices and the reader reserved 3 * count doubles up front (48 GB), which
// threw std::bad_alloc (or aborted under AddressSanitizer) instead of reading
// to the end of the file and reporting it as truncated.
#include <gtest/gtest.h>

#include <string>

#include "io_read_helpers.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/mesh_io.hpp"

namespace pqmesh::test {
namespace {

// The file holds one vertex where 2147483646 are announced, so the reader runs
// out of tokens on the line after the single vertex.
template <class Read>
void expect_truncated(Read read, const std::string& path) {
  try {
    read(path);
    ADD_FAILURE() << "no ParseError for " << path;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), ErrorCode::Truncated) << e.what();
    EXPECT_EQ(e.file(), path);
  }
}

TEST(FuzzRegression, MeditHugeVertexCount) {
  const std::string path = write_temp("fuzz_huge.mesh",
                                      "MeshVersionFormatted 2\nDimension 3\nVertices\n2147483646\n0 0 0 0\n");
  expect_truncated([](const std::string& p) { return read_tetmesh(p); }, path);
}

TEST(FuzzRegression, Gmsh22HugeNodeCount) {
  const std::string path =
      write_temp("fuzz_huge22.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2147483646\n1 0 0 0\n");
  expect_truncated([](const std::string& p) { return read_tetmesh(p); }, path);
}

TEST(FuzzRegression, Gmsh41HugeNodeCount) {
  // 1 block, 2147483646 nodes in total, tags 1..2147483646; the block claims them all.
  const std::string path = write_temp("fuzz_huge41.msh",
                                      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2147483646 1 2147483646\n"
                                      "3 1 0 2147483646\n1\n");
  expect_truncated([](const std::string& p) { return read_tetmesh(p); }, path);
}

TEST(FuzzRegression, TetgenHugeNodeCount) {
  write_temp("fuzz_huge_tg.ele", "1 4 0\n1 1 2 3 4\n");
  write_temp("fuzz_huge_tg.face", "0 0\n");
  const std::string path = write_temp("fuzz_huge_tg.node", "2147483646 3 0 0\n1 0 0 0\n");
  expect_truncated([](const std::string& p) { return read_tetmesh(p); }, path);
}

TEST(FuzzRegression, VtuHugePointCount) {
  // A valid ASCII .vtu of one tetrahedron whose <Piece> then announces 2e9
  // points: the Points array holds 12 values where 6e9 are expected.
  TetMesh3 mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.tetrahedra = {{0, 1, 2, 3}};
  const std::string path = write_temp("fuzz_huge.vtu", "");
  WriteOptions ascii;
  ascii.binary = false;
  write_mesh(mesh, path, ascii);
  std::string text;
  {
    std::ifstream in(path, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string from = "NumberOfPoints=\"4\"";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "NumberOfPoints=\"2000000000\"");
  write_temp("fuzz_huge.vtu", text);
  try {
    read_tetmesh(path);
    ADD_FAILURE() << "no ParseError for " << path;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), path) << e.what();
  }
}

}  // namespace
}  // namespace pqmesh::test
