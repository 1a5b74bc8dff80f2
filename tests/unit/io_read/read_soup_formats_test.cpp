// OFF, OBJ, Medit and STL reading of small cubes, with coplanar merging.
// The cube fixtures list the unit cube's faces (outward, counter-clockwise seen
// from outside) either as quadrilaterals or as two triangles each.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <set>

#include "io_read_helpers.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh {
namespace {

using test::fixture;

double axis_value(const Vec3& p, int a) { return a == 0 ? p.x : (a == 1 ? p.y : p.z); }

// Every facet is one 4-vertex loop lying on a distinct face of the unit cube
// and turning counter-clockwise seen from outside (its Newell normal points
// away from the cube).
void expect_unit_cube_quads(const Plc3& p) {
  ASSERT_EQ(p.facets.size(), 6u);
  std::set<std::pair<int, double>> faces;
  for (const Facet3& f : p.facets) {
    ASSERT_EQ(f.loops.size(), 1u);
    const auto& loop = f.loops[0];
    ASSERT_EQ(loop.size(), 4u);
    Vec3 n;
    for (std::size_t i = 0; i < 4; ++i) n = n + cross(p.vertices[loop[i]], p.vertices[loop[(i + 1) % 4]]);
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      bool fixed = true;
      for (int v : loop) fixed = fixed && axis_value(p.vertices[v], a) == axis_value(p.vertices[loop[0]], a);
      if (fixed) axis = a;
    }
    ASSERT_GE(axis, 0);
    const double value = axis_value(p.vertices[loop[0]], axis);
    EXPECT_GT(axis_value(n, axis) * (value == 1 ? 1 : -1), 0) << "facet not outward";
    faces.insert({axis, value});
  }
  EXPECT_EQ(faces.size(), 6u);
}

TEST(ReadOff, CubeQuads) {
  ReadReport report;
  const Plc3 p = read_plc(fixture("cube.off"), {}, &report);
  ASSERT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.vertices[5], (Vec3{1, 0, 1}));
  EXPECT_EQ(p.facets[0].loops[0], (std::vector<int>{0, 2, 3, 1}));
  expect_unit_cube_quads(p);
  EXPECT_EQ(report.input_polygons, 6);
  EXPECT_EQ(report.merged_exact, 0);  // neighbouring cube faces are not coplanar
  EXPECT_EQ(p.source.first_id, 0);
  EXPECT_EQ(p.source.line_of_vertex(0), 4);
  EXPECT_EQ(p.source.line_of_element(0), 12);
}

TEST(ReadObj, CubeTrianglesMerge) {
  ReadReport report;
  const Plc3 p = read_plc(fixture("cube.obj"), {}, &report);
  ASSERT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.source.first_id, 1);
  expect_unit_cube_quads(p);
  EXPECT_EQ(report.input_polygons, 12);
  EXPECT_EQ(report.facets, 6);
  EXPECT_EQ(report.merged_exact, 6);
  // Facet of the first face starts at "f 1 3 4" (line 13); the y = 0 face comes
  // from the relative-index lines 17-18.
  EXPECT_EQ(p.source.line_of_element(0), 13);
  EXPECT_EQ(p.source.line_of_element(2), 17);
}

TEST(ReadObj, NoMergeKeepsTriangles) {
  ReadReport report;
  ReadOptions options;
  options.merge_coplanar = false;
  const Plc3 p = read_plc(fixture("cube.obj"), options, &report);
  ASSERT_EQ(p.facets.size(), 12u);
  // "f -8 -3 -4" with 8 vertices read: ids 1 6 5 -> indices 0 5 4.
  EXPECT_EQ(p.facets[5].loops[0], (std::vector<int>{0, 5, 4}));
  EXPECT_EQ(report.merged_exact, 0);
}

TEST(ReadMedit, RefsBecomeMarkersAndSeparateFacets) {
  ReadReport report;
  const Plc3 p = read_plc(fixture("cube.mesh"), {}, &report);
  ASSERT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{1, 1, 1, 1, 2, 2, 2, 2}));
  // The top face's triangles carry refs 5 and 6, so they stay apart: 5 merged
  // faces + 2 triangles.
  ASSERT_EQ(p.facets.size(), 7u);
  EXPECT_EQ(report.merged_exact, 5);
  std::vector<int> markers;
  for (const Facet3& f : p.facets) markers.push_back(f.marker);
  EXPECT_EQ(markers, (std::vector<int>{1, 5, 6, 3, 4, 7, 8}));
  EXPECT_EQ(p.facets[1].loops[0], (std::vector<int>{4, 5, 7}));
  EXPECT_EQ(p.source.line_of_vertex(0), 6);
  EXPECT_EQ(p.source.line_of_element(2), 19);
}

// The 12 triangles of cube_ascii.stl, as (x, y, z) corners.
std::vector<std::array<float, 9>> cube_triangles() {
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  auto corner = [](int i) { return std::array<float, 3>{float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)}; };
  std::vector<std::array<float, 9>> out;
  for (const auto& q : quads)
    for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      std::array<float, 9> tri{};
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) tri[3 * k + c] = corner(t[k])[c];
      out.push_back(tri);
    }
  return out;
}

std::string binary_stl(const std::vector<std::array<float, 9>>& tris, const std::string& header, std::uint32_t count) {
  std::string bytes(80, ' ');
  std::memcpy(bytes.data(), header.data(), std::min<std::size_t>(header.size(), 80));
  bytes.append(reinterpret_cast<const char*>(&count), 4);  // the test machine is little-endian
  for (const auto& t : tris) {
    const float normal[3] = {0, 0, 0};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    bytes.append(reinterpret_cast<const char*>(t.data()), 36);
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST(ReadStl, AsciiCubeMergesIntoSixQuads) {
  ReadReport report;
  const Plc3 p = read_plc(fixture("cube_ascii.stl"), {}, &report);
  ASSERT_EQ(p.vertices.size(), 8u);
  expect_unit_cube_quads(p);
  EXPECT_EQ(report.input_polygons, 12);
  EXPECT_EQ(report.facets, 6);
  EXPECT_EQ(report.merged_exact, 6);
  EXPECT_EQ(report.welded_vertices, 36 - 8);
  // First vertices by appearance: (0,0,0) (0,1,0) (1,1,0) on lines 4, 5, 6.
  EXPECT_EQ(p.vertices[1], (Vec3{0, 1, 0}));
  EXPECT_EQ(p.source.vertex_line[0], 4);
  EXPECT_EQ(p.source.vertex_line[2], 6);
  EXPECT_EQ(p.source.element_line[1], 16);  // second face starts at the third "facet" (line 2 + 2*7)
}

TEST(ReadStl, BinaryWithSolidHeaderEqualsAscii) {
  const std::string path =
      test::write_temp("cube_binary.stl", binary_stl(cube_triangles(), "solid looks like ascii", 12));
  ReadReport rb, ra;
  const Plc3 b = read_plc(path, {}, &rb);
  const Plc3 a = read_plc(fixture("cube_ascii.stl"), {}, &ra);
  EXPECT_EQ(b.vertices, a.vertices);
  ASSERT_EQ(b.facets.size(), a.facets.size());
  for (std::size_t i = 0; i < a.facets.size(); ++i) {
    EXPECT_EQ(b.facets[i].loops, a.facets[i].loops);
    EXPECT_EQ(b.facets[i].marker, a.facets[i].marker);
  }
  EXPECT_EQ(rb.welded_vertices, 28);
  EXPECT_TRUE(b.source.vertex_line.empty());
}

TEST(ReadStl, NegativeZeroWeldsWithZero) {
  auto tris = cube_triangles();
  for (auto& t : tris)
    for (float& c : t)
      if (c == 0) c = -0.0f;
  tris[0][0] = 0.0f;  // one positive zero among the negative ones
  const std::string path = test::write_temp("cube_negzero.stl", binary_stl(tris, "binary", 12));
  const Plc3 p = read_plc(path);
  EXPECT_EQ(p.vertices.size(), 8u);
  expect_unit_cube_quads(p);
}

TEST(ReadStl, BinaryErrors) {
  const auto tris = cube_triangles();
  // Announces 12 triangles but holds 11: not binary by size, not "solid": truncated.
  std::string bytes = binary_stl(tris, "binary", 12);
  bytes.resize(bytes.size() - 50);
  const std::string truncated = test::write_temp("truncated.stl", bytes);
  test::expect_parse_error([&] { read_plc(truncated); }, {ErrorCode::Truncated, 0, {}}, truncated);
  // A NaN corner in triangle 3.
  auto bad = tris;
  bad[3][4] = std::numeric_limits<float>::quiet_NaN();
  const std::string nan_path = test::write_temp("nan.stl", binary_stl(bad, "binary", 12));
  test::expect_parse_error([&] { read_plc(nan_path); }, {ErrorCode::NonFinite, 0, {3}}, nan_path);
}

}  // namespace
}  // namespace pqmesh
