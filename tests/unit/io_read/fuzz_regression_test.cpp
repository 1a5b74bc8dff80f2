// Regression tests for inputs found by mutation fuzzing of the readers, and
// damaged compressed .vtu arrays. Each input is the minimised file; the promise under test is "bad input gets a
// ParseError, never a crash": before the fix each of these announced ~2^31
// vertices and the reader reserved 3 * count doubles up front (48 GB), which
// threw std::bad_alloc (or aborted under AddressSanitizer) instead of reading
// to the end of the file and reporting it as truncated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
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

// Compressed .vtu arrays (vtkZLibDataCompressor, src/io/vtu_compression.cpp):
// a one-tetrahedron file written with WriteOptions::compress, then damaged.
// The appended arrays are in reverse document order, so "types" is the first
// block after '_': header [1 block, 65536, last block 1 byte, compressed
// size] as UInt64, then its zlib stream. Every damage gets a ParseError with
// the file and the line of the damaged DataArray, never a crash or a huge
// allocation.
struct CompressedVtu {
  std::string path, text;
  std::size_t data = 0;  // first byte after '_'
  int line_of(const std::string& name) const {
    const std::size_t at = text.find("Name=\"" + name + "\"");
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  }
  void put64(std::size_t at, std::uint64_t v) {
    for (int k = 0; k < 8; ++k) text[at + k] = static_cast<char>((v >> (8 * k)) & 0xff);
  }
};

CompressedVtu compressed_tetrahedron(const std::string& name) {
  TetMesh3 mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.tetrahedra = {{0, 1, 2, 3}};
  CompressedVtu f;
  f.path = write_temp(name, "");
  WriteOptions options;
  options.compress = true;
  write_mesh(mesh, f.path, options);
  std::ifstream in(f.path, std::ios::binary);
  f.text.assign(std::istreambuf_iterator<char>(in), {});
  f.data = f.text.find('_', f.text.find("<AppendedData")) + 1;
  return f;
}

void expect_error(const CompressedVtu& f, ErrorCode code, const std::string& array) {
  write_temp(f.path.substr(f.path.rfind('/') + 1), f.text);
  try {
    read_tetmesh(f.path);
    ADD_FAILURE() << "no ParseError for " << f.path;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_EQ(e.file(), f.path) << e.what();
    EXPECT_EQ(e.line(), f.line_of(array)) << e.what();
    EXPECT_NE(std::string(e.what()).find(array), std::string::npos) << e.what();
  }
}

TEST(FuzzRegression, VtuCompressedIntactFileReads) {
  const CompressedVtu f = compressed_tetrahedron("zlib_ok.vtu");
  EXPECT_EQ(read_tetmesh(f.path).tetrahedra.size(), 1u);
}

TEST(FuzzRegression, VtuCompressedHugeBlockCount) {
  CompressedVtu f = compressed_tetrahedron("zlib_blocks.vtu");
  f.put64(f.data, std::uint64_t{1} << 40);  // 2^40 blocks: a header of 8 TB
  expect_error(f, ErrorCode::WrongCount, "types");
}

TEST(FuzzRegression, VtuCompressedWrongBlockSizes) {
  CompressedVtu f = compressed_tetrahedron("zlib_sizes.vtu");
  f.put64(f.data + 16, 2);  // last block 2 bytes, but the mesh has 1 cell (1 type byte)
  expect_error(f, ErrorCode::WrongCount, "types");
  f.put64(f.data + 16, 1);
  f.put64(f.data + 8, std::uint64_t{1} << 62);  // block size 2^62 with 1 block: still 1 byte in all
  write_temp("zlib_sizes.vtu", f.text);
  EXPECT_EQ(read_tetmesh(f.path).tetrahedra.size(), 1u);
}

TEST(FuzzRegression, VtuCompressedBlockPastTheEnd) {
  CompressedVtu f = compressed_tetrahedron("zlib_past.vtu");
  f.put64(f.data + 24, std::uint64_t{1} << 50);
  expect_error(f, ErrorCode::Truncated, "types");
}

TEST(FuzzRegression, VtuCompressedCorruptZlibStream) {
  CompressedVtu f = compressed_tetrahedron("zlib_corrupt.vtu");
  for (std::size_t k = 0; k < 4; ++k) f.text[f.data + 32 + k] = '\xff';
  expect_error(f, ErrorCode::Syntax, "types");
}

TEST(FuzzRegression, VtuCompressedTruncatedFile) {
  CompressedVtu f = compressed_tetrahedron("zlib_cut.vtu");
  // Points is the last block (first in the document): keep its header, cut its stream.
  const std::size_t points = f.text.find("Name=\"Points\"");
  const std::size_t offset = std::stoull(f.text.substr(f.text.find("offset=\"", points) + 8));
  f.text.resize(f.data + offset + 32 + 3);
  expect_error(f, ErrorCode::Truncated, "Points");
}

}  // namespace
}  // namespace pqmesh::test
