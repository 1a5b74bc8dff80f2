// File contents that matter to other programs, atomic writing, and readers
// rejecting malformed files with ParseError naming the line.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pqmesh/mesh_io.hpp"
#include "sample_meshes.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

std::string slurp(const std::filesystem::path& p) { return test::file_bytes(p.string()); }

void spit(const std::filesystem::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

std::size_t files_in(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

// Marker -> physical tag: markers {7, -2}: 7 -> 7, -2 -> M + 1 - m = 7 + 1 + 2 = 10.
// Without markers every element has marker 0 -> tag 0 + 1 - 0 = 1.
TEST(GmshFile, PhysicalTagsAndNames) {
  const auto dir = test::scratch_dir("gmsh_tags");
  write_mesh(test::square_mesh(true), (dir / "a.msh").string());
  const std::string text = slurp(dir / "a.msh");
  EXPECT_NE(text.find("$MeshFormat\n4.1 0 8\n"), std::string::npos);
  EXPECT_NE(text.find("2 7 \"marker 7\"\n"), std::string::npos);
  EXPECT_NE(text.find("2 10 \"marker -2\"\n"), std::string::npos);
  EXPECT_NE(text.find("1 4 \"marker 4\"\n"), std::string::npos);
  // $Entities: 4 curves (edge markers 1..4), 2 surfaces (triangle markers).
  EXPECT_NE(text.find("$Entities\n0 4 2 0\n"), std::string::npos);
  WriteOptions v22;
  v22.format = MeshFormat::Msh22;
  write_mesh(test::square_mesh(false), (dir / "b.msh").string(), v22);
  const std::string plain = slurp(dir / "b.msh");
  EXPECT_NE(plain.find("2 1 \"marker 0\"\n"), std::string::npos);
  // Element 1: triangle (type 2), 2 tags: physical 1, entity 1, nodes 1 2 3.
  EXPECT_NE(plain.find("\n1 2 2 1 1 1 2 3\n"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// TetGen's .face lists boundary triangles with the normal pointing into the
// volume: the writer reverses pqmesh's outward triangles.
TEST(TetgenFile, FacesReversedElementsNot) {
  const auto dir = test::scratch_dir("tetgen_faces");
  const TetMesh3 cube = test::cube_mesh(true);
  write_mesh(cube, (dir / "c.node").string());
  const std::string face = slurp(dir / "c.face");
  const auto& f = cube.faces[0];
  const std::string expected = "\n1 " + std::to_string(f[0] + 1) + " " + std::to_string(f[2] + 1) + " " +
                               std::to_string(f[1] + 1) + " " + std::to_string(cube.face_markers[0]) + "\n";
  EXPECT_NE(face.find(expected), std::string::npos) << face;
  const std::string ele = slurp(dir / "c.ele");
  EXPECT_EQ(ele.substr(0, ele.find('\n', ele.find('\n') + 1) + 1), "6 4 1\n1 1 2 4 8 1\n");
  std::filesystem::remove_all(dir);
}

// A clockwise triangle and a negative tetrahedron in a file come back in the
// file's vertex order: readers never hide an orientation error from the checker.
TEST(Readers, KeepFileOrientation) {
  const auto dir = test::scratch_dir("reorient");
  spit(dir / "t.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n");
  spit(dir / "t.ele", "1 3 0\n1 1 3 2\n");
  const TriMesh2 tri = read_trimesh((dir / "t.node").string());
  ASSERT_EQ(tri.triangles.size(), 1u);
  EXPECT_EQ(tri.triangles[0], (std::array<int, 3>{0, 2, 1}));
  spit(dir / "k.node", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");  // 0-based
  spit(dir / "k.ele", "1 4 0\n0 0 2 1 3\n");
  const TetMesh3 tet = read_tetmesh((dir / "k.ele").string());
  ASSERT_EQ(tet.tetrahedra.size(), 1u);
  EXPECT_EQ(tet.tetrahedra[0], (std::array<int, 4>{0, 2, 1, 3}));
  std::filesystem::remove_all(dir);
}

TEST(VtuFile, CellDataAndAscii) {
  const auto dir = test::scratch_dir("vtu_fields");
  WriteOptions options;
  options.binary = false;
  options.cell_fields = {{"min_angle", {45.0, 45.0}}};
  write_mesh(test::square_mesh(true), (dir / "s.vtu").string(), options);
  const std::string text = slurp(dir / "s.vtu");
  EXPECT_NE(text.find("Name=\"min_angle\" format=\"ascii\">\n45 45\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"marker\" format=\"ascii\">\n7 -2\n"), std::string::npos);
  EXPECT_NE(text.find("Name=\"types\" format=\"ascii\">\n5 5\n"), std::string::npos);
  options.cell_fields[0].values.pop_back();
  EXPECT_THROW(write_mesh(test::square_mesh(true), (dir / "bad.vtu").string(), options), InvalidInput);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.vtu"));
  std::filesystem::remove_all(dir);
}

// The square's triangles are right isosceles: smallest angle 45 degrees, the
// [40, 50) class; y is flipped, so vertex 3 (top left, y max) is at y = 10.
TEST(SvgFile, Picture) {
  const auto dir = test::scratch_dir("svg");
  WriteOptions options;
  options.svg_width = 300;
  write_mesh(test::square_mesh(true), (dir / "s.svg").string(), options);
  const std::string text = slurp(dir / "s.svg");
  EXPECT_NE(text.find("viewBox=\"0 0 560.000 360.000\""), std::string::npos) << text;
  EXPECT_EQ(count_of(text, "<polygon "), 2u);
  EXPECT_EQ(count_of(text, "<polyline "), 4u);
  EXPECT_NE(text.find("<g fill=\"#a6d96a\""), std::string::npos);
  EXPECT_NE(text.find("40-50&#176;: 2<"), std::string::npos);
  EXPECT_NE(text.find("<polygon points=\"10.000,310.000 310.000,310.000 310.000,10.000\"/>"), std::string::npos);
  EXPECT_THROW(write_mesh(test::cube_mesh(true), (dir / "c.svg").string()), ParseError);
  EXPECT_THROW(read_trimesh((dir / "s.svg").string()), ParseError);
  std::filesystem::remove_all(dir);
}

TEST(AtomicWrite, MissingDirectoryLeavesNothing) {
  const auto dir = test::scratch_dir("atomic_missing");
  const auto path = dir / "no" / "such" / "m.vtu";
  EXPECT_THROW(write_mesh(test::square_mesh(true), path.string()), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
  EXPECT_EQ(files_in(dir), 0u);
  std::filesystem::remove_all(dir);
}

// A write that fails half-way (the file size limit is hit after the first
// megabyte) throws and leaves neither the file nor its temporary.
TEST(AtomicWrite, FailureMidwayLeavesNothing) {
  const auto dir = test::scratch_dir("atomic_midway");
  TetMesh3 big;
  for (int i = 0; i < 200000; ++i) big.vertices.push_back({i * 0.1, i / 3.0, i / 7.0});
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  auto previous = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = old;
  limited.rlim_cur = 1 << 20;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  for (const char* name : {"big.msh", "big.vtu", "big.mesh", "big.node"})
    EXPECT_THROW(write_mesh(big, (dir / name).string()), Error) << name;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &old), 0);
  std::signal(SIGXFSZ, previous);
  EXPECT_EQ(files_in(dir), 0u);
  std::filesystem::remove_all(dir);
}

// A failure on the second of three TetGen files leaves none of them.
TEST(AtomicWrite, WriterChecksBeforeCreatingFiles) {
  const auto dir = test::scratch_dir("atomic_check");
  TetMesh3 bad = test::cube_mesh(true);
  bad.tetrahedra[3][2] = 8;  // no vertex 8
  try {
    write_mesh(bad, (dir / "c.node").string());
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.code(), ErrorCode::IndexOutOfRange);
    EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{3, 8}));
  }
  EXPECT_EQ(files_in(dir), 0u);
  std::filesystem::remove_all(dir);
}

struct BadFile {
  const char* name;
  const char* file;
  const char* text;
  ErrorCode code;
  int line;
  bool three_d;
};

const BadFile kBadFiles[] = {
    {"msh41_missing_node", "a.msh",
     "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
     "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 9\n$EndElements\n",
     ErrorCode::IndexOutOfRange, 17, false},
    {"msh22_bad_number", "a.msh",
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1.0x 0 0\n3 0 1 0\n$EndNodes\n",
     ErrorCode::Syntax, 7, false},
    {"msh22_truncated", "a.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n",
     ErrorCode::Truncated, 8, false},
    {"msh_binary", "a.msh", "$MeshFormat\n4.1 1 8\n", ErrorCode::Unsupported, 2, false},
    {"msh_quad_in_trimesh", "a.msh",
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
     "$Elements\n1\n1 3 2 1 1 1 2 3 4\n$EndElements\n",
     ErrorCode::Unsupported, 13, false},
    {"medit_bad_vertex", "a.mesh",
     "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
     "Tetrahedra\n1\n1 2 3 5 0\nEnd\n",
     ErrorCode::IndexOutOfRange, 11, true},
    {"medit_nan", "a.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n1\nnan 0 0\nEnd\n",
     ErrorCode::NonFinite, 5, false},
    {"tetgen_bad_count", "a.node", "# comment\n2 2 0 0\n1 0 0\n", ErrorCode::Truncated, 4, false},
    {"vtu_bad_value", "a.vtu",
     "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n<UnstructuredGrid>\n"
     "<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n<Points>\n"
     "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n0 zero 0\n</DataArray>\n</Points>\n"
     "<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\"></DataArray>\n"
     "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\"></DataArray>\n"
     "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\"></DataArray>\n</Cells>\n</Piece>\n"
     "</UnstructuredGrid>\n</VTKFile>\n",
     ErrorCode::Syntax, 6, false},
    {"missing_file", "nothing.msh", nullptr, ErrorCode::Unreadable, 0, false},
};

class MalformedFile : public ::testing::TestWithParam<int> {};

TEST_P(MalformedFile, ParseErrorNamesLine) {
  const BadFile& bad = kBadFiles[GetParam()];
  const auto dir = test::scratch_dir(std::string("bad_") + bad.name);
  const auto path = dir / bad.file;
  if (bad.text != nullptr) spit(path, bad.text);
  if (std::string(bad.file) == "a.node") spit(dir / "a.ele", "0 3 0\n");
  try {
    if (bad.three_d)
      read_tetmesh(path.string());
    else
      read_trimesh(path.string());
    FAIL() << "no exception";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), bad.code) << e.what();
    EXPECT_EQ(e.line(), bad.line) << e.what();
    EXPECT_EQ(e.file(), path.string());
  }
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedFile, ::testing::Range(0, static_cast<int>(std::size(kBadFiles))),
                         [](const auto& param_info) { return std::string(kBadFiles[param_info.param].name); });

}  // namespace
}  // namespace pqmesh
