// The .vtu writer's slim array types (src/io/mesh_vtu.cpp): Int32
// connectivity/offsets when every offset fits, Float32 for cell fields that
// ask for single precision (each value the nearest float; values beyond the
// float range, infinities included, saturate at +-FLT_MAX), Float64 otherwise. The
// expected values are derived here from the inputs, not copied from a file.
#include <gtest/gtest.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "pqmesh/mesh_io.hpp"
#include "sample_meshes.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

std::string slurp(const std::filesystem::path& p) { return test::file_bytes(p.string()); }

// The float each double of a single-precision field must become.
float expected_float(double v) {
  constexpr float kMax = std::numeric_limits<float>::max();
  if (v > static_cast<double>(kMax)) return kMax;
  if (v < -static_cast<double>(kMax)) return -kMax;
  return static_cast<float>(v);
}

// Bytes of the appended array declared by `declaration` (the DataArray tag
// up to and including its offset attribute's opening quote).
std::string appended_array(const std::string& file, const std::string& declaration) {
  const std::size_t tag = file.find(declaration);
  EXPECT_NE(tag, std::string::npos) << declaration;
  if (tag == std::string::npos) return {};
  std::size_t offset = 0;
  const std::size_t digits = tag + declaration.size();
  std::from_chars(file.data() + digits, file.data() + file.size(), offset);
  const std::size_t start = file.find('_', file.find("<AppendedData")) + 1 + offset;
  std::uint64_t size = 0;
  std::memcpy(&size, file.data() + start, 8);  // little-endian host (the raw fast path)
  return file.substr(start + 8, size);
}

// 6 tetrahedra: one value per cell, including three beyond the float range.
const std::vector<double> kValues = {0.25, 1.0 / 7, 1e300, -1e300, 1e-300, std::numeric_limits<double>::infinity()};

WriteOptions field_options(bool binary) {
  WriteOptions options;
  options.binary = binary;
  options.cell_fields = {{"q64", kValues}, {"q32", kValues, true}};
  return options;
}

TEST(VtuTypes, BinaryInt32IndicesAndFloat32Fields) {
  const auto dir = test::scratch_dir("vtu_types_binary");
  const TetMesh3 mesh = test::cube_mesh(true);
  const std::string path = (dir / "m.vtu").string();
  write_mesh(mesh, path, field_options(true));
  const std::string file = slurp(path);

  const std::string q32 = appended_array(file, "<DataArray type=\"Float32\" Name=\"q32\" format=\"appended\" offset=\"");
  ASSERT_EQ(q32.size(), 4 * kValues.size());
  for (std::size_t i = 0; i < kValues.size(); ++i) {
    float f = 0;
    std::memcpy(&f, q32.data() + 4 * i, 4);
    EXPECT_EQ(f, expected_float(kValues[i])) << i;
  }
  const std::string q64 = appended_array(file, "<DataArray type=\"Float64\" Name=\"q64\" format=\"appended\" offset=\"");
  ASSERT_EQ(q64.size(), 8 * kValues.size());
  EXPECT_EQ(std::memcmp(q64.data(), kValues.data(), q64.size()), 0);

  const std::string conn =
      appended_array(file, "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"appended\" offset=\"");
  ASSERT_EQ(conn.size(), 4 * 4 * mesh.tetrahedra.size());
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for (std::size_t k = 0; k < 4; ++k) {
      std::int32_t v = 0;
      std::memcpy(&v, conn.data() + 4 * (4 * t + k), 4);
      EXPECT_EQ(v, mesh.tetrahedra[t][k]) << t << ' ' << k;
    }
  const std::string offsets =
      appended_array(file, "<DataArray type=\"Int32\" Name=\"offsets\" format=\"appended\" offset=\"");
  ASSERT_EQ(offsets.size(), 4 * mesh.tetrahedra.size());
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    std::int32_t v = 0;
    std::memcpy(&v, offsets.data() + 4 * t, 4);
    EXPECT_EQ(v, static_cast<std::int32_t>(4 * (t + 1))) << t;
  }

  // The readers take the slim types back: the same mesh.
  const TetMesh3 back = read_tetmesh(path);
  EXPECT_EQ(back.tetrahedra, mesh.tetrahedra);
  EXPECT_EQ(back.tetrahedron_markers, mesh.tetrahedron_markers);
  std::filesystem::remove_all(dir);
}

TEST(VtuTypes, AsciiFloat32FieldsReadBackAsTheNearestFloat) {
  const auto dir = test::scratch_dir("vtu_types_ascii");
  const TriMesh2 mesh = test::square_mesh(true);
  const std::string path = (dir / "m.vtu").string();
  WriteOptions options = field_options(false);
  for (auto& f : options.cell_fields) f.values.resize(mesh.triangles.size());  // 2 triangles: 0.25, 1/7
  write_mesh(mesh, path, options);
  const std::string file = slurp(path);
  const std::string head = "<DataArray type=\"Float32\" Name=\"q32\" format=\"ascii\">\n";
  const std::size_t at = file.find(head);
  ASSERT_NE(at, std::string::npos);
  const char* p = file.data() + at + head.size();
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    float f = 0;
    const auto [next, ec] = std::from_chars(p, file.data() + file.size(), f);
    ASSERT_EQ(ec, std::errc()) << i;
    EXPECT_EQ(f, expected_float(kValues[i])) << i;
    p = next + 1;
  }
  EXPECT_NE(file.find("<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">"), std::string::npos);
  const TriMesh2 back = read_trimesh(path);
  EXPECT_EQ(back.triangles, mesh.triangles);
  EXPECT_EQ(back.triangle_markers, mesh.triangle_markers);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pqmesh
