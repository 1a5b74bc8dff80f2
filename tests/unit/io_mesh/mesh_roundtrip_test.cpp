// Round trips write -> read for every format and both mesh kinds, with and
// without markers: coordinates bit-exact, connectivity and markers equal.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "predicates/predicates.hpp"
#include "pqmesh/mesh_io.hpp"
#include "sample_meshes.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

struct FormatCase {
  const char* name;
  const char* file;  // file name written
  MeshFormat format;
  bool binary;
  bool keeps_boundary;  // .vtu holds the elements only
};

const FormatCase kCases[] = {
    {"vtu_binary", "m.vtu", MeshFormat::Vtu, true, false},  {"vtu_ascii", "m.vtu", MeshFormat::Vtu, false, false},
    {"msh41", "m.msh", MeshFormat::Msh41, false, true},     {"msh22", "m.msh", MeshFormat::Msh22, false, true},
    {"medit", "m.mesh", MeshFormat::Medit, false, true},    {"tetgen", "m.node", MeshFormat::TetgenNodeEle, false, true},
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string slurp(const std::filesystem::path& p) { return test::file_bytes(p.string()); }

class RoundTrip : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(RoundTrip, TriMesh2) {
  const FormatCase& fc = kCases[std::get<0>(GetParam())];
  const bool markers = std::get<1>(GetParam());
  const auto dir = test::scratch_dir(std::string("rt2_") + fc.name + (markers ? "_m" : ""));
  const TriMesh2 mesh = test::square_mesh(markers);
  WriteOptions options;
  options.format = fc.format;
  options.binary = fc.binary;
  const std::string path = (dir / fc.file).string();
  write_mesh(mesh, path, options);
  const TriMesh2 back = read_trimesh(path);
  ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    EXPECT_TRUE(same_bits(back.vertices[i].x, mesh.vertices[i].x)) << i;
    EXPECT_TRUE(same_bits(back.vertices[i].y, mesh.vertices[i].y)) << i;
  }
  EXPECT_EQ(back.triangles, mesh.triangles);
  EXPECT_EQ(back.triangle_markers, mesh.triangle_markers);
  EXPECT_EQ(back.vertex_markers, mesh.vertex_markers);
  if (fc.keeps_boundary) {
    EXPECT_EQ(back.edges, mesh.edges);
    EXPECT_EQ(back.edge_markers, mesh.edge_markers);
  } else {
    EXPECT_TRUE(back.edges.empty());
  }
  std::filesystem::remove_all(dir);
}

TEST_P(RoundTrip, TetMesh3) {
  const FormatCase& fc = kCases[std::get<0>(GetParam())];
  const bool markers = std::get<1>(GetParam());
  const auto dir = test::scratch_dir(std::string("rt3_") + fc.name + (markers ? "_m" : ""));
  const TetMesh3 mesh = test::cube_mesh(markers);
  WriteOptions options;
  options.format = fc.format;
  options.binary = fc.binary;
  const std::string path = (dir / fc.file).string();
  write_mesh(mesh, path, options);
  const TetMesh3 back = read_tetmesh(path);
  ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    EXPECT_TRUE(same_bits(back.vertices[i].x, mesh.vertices[i].x)) << i;
    EXPECT_TRUE(same_bits(back.vertices[i].y, mesh.vertices[i].y)) << i;
    EXPECT_TRUE(same_bits(back.vertices[i].z, mesh.vertices[i].z)) << i;
  }
  EXPECT_EQ(back.tetrahedra, mesh.tetrahedra);
  EXPECT_EQ(back.tetrahedron_markers, mesh.tetrahedron_markers);
  EXPECT_EQ(back.vertex_markers, mesh.vertex_markers);
  if (fc.keeps_boundary) {
    EXPECT_EQ(back.faces, mesh.faces);
    EXPECT_EQ(back.face_markers, mesh.face_markers);
  } else {
    EXPECT_TRUE(back.faces.empty());
  }
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, RoundTrip,
                         ::testing::Combine(::testing::Range(0, static_cast<int>(std::size(kCases))),
                                            ::testing::Bool()),
                         [](const auto& param_info) {
                           return std::string(kCases[std::get<0>(param_info.param)].name) +
                                  (std::get<1>(param_info.param) ? "_markers" : "_plain");
                         });

// The hand-built samples satisfy pqmesh's orientation convention, so the
// round trips above also show that no writer/reader pair flips elements.
TEST(SampleMeshes, Orientation) {
  const TetMesh3 cube = test::cube_mesh(true);
  ASSERT_EQ(cube.tetrahedra.size(), 6u);
  ASSERT_EQ(cube.faces.size(), 12u);  // two per cube side
  for (const auto& t : cube.tetrahedra)
    EXPECT_EQ(orient3d(cube.vertices[t[0]], cube.vertices[t[1]], cube.vertices[t[2]], cube.vertices[t[3]]),
              Sign::Positive);
  // Outward faces: the cube centre is on the negative side of every face.
  const Vec3 centre{1.0 / 3.0 + 0.05, 1.0 / 3.0 + 0.05, 1.0 / 3.0 + 0.05};
  for (const auto& f : cube.faces)
    EXPECT_EQ(orient3d(cube.vertices[f[0]], cube.vertices[f[1]], cube.vertices[f[2]], centre), Sign::Negative);
  const TriMesh2 sq = test::square_mesh(true);
  for (const auto& t : sq.triangles)
    EXPECT_EQ(orient2d(sq.vertices[t[0]], sq.vertices[t[1]], sq.vertices[t[2]]), Sign::Positive);
}

// Writing the same mesh twice gives identical bytes in every format.
TEST(Determinism, SameBytes) {
  const auto dir = test::scratch_dir("determinism");
  WriteOptions options;
  options.cell_fields = {{"quality", {0.25, 1.0 / 7, 0.5, 0.75, 1e-300, 2.5}}};
  for (const FormatCase& fc : kCases) {
    options.format = fc.format;
    options.binary = fc.binary;
    const std::string ext = std::filesystem::path(fc.file).extension().string();
    const auto a = dir / ("a" + ext), b = dir / ("b" + ext);
    write_mesh(test::cube_mesh(true), a.string(), options);
    write_mesh(test::cube_mesh(true), b.string(), options);
    EXPECT_EQ(slurp(a), slurp(b)) << fc.name;
    EXPECT_FALSE(slurp(a).empty()) << fc.name;
  }
  std::filesystem::remove_all(dir);
}

// Format from file name.
TEST(MeshFormatFromPath, Extensions) {
  EXPECT_EQ(mesh_format_from_path("a/b.vtu"), MeshFormat::Vtu);
  EXPECT_EQ(mesh_format_from_path("b.msh"), MeshFormat::Msh41);
  EXPECT_EQ(mesh_format_from_path("b.msh", true), MeshFormat::Msh22);
  EXPECT_EQ(mesh_format_from_path("b.mesh"), MeshFormat::Medit);
  EXPECT_EQ(mesh_format_from_path("b.node"), MeshFormat::TetgenNodeEle);
  EXPECT_EQ(mesh_format_from_path("b.ele"), MeshFormat::TetgenNodeEle);
  EXPECT_EQ(mesh_format_from_path("b.svg"), MeshFormat::Svg);
  try {
    mesh_format_from_path("b.stl");
    FAIL() << "no exception";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.code(), ErrorCode::Unsupported);
    EXPECT_EQ(e.file(), "b.stl");
  }
}

}  // namespace
}  // namespace pqmesh
