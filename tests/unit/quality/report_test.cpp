// Whole-mesh quality: element_quality, quality_report, to_text, histogram_svg.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>

#include "pqmesh/errors.hpp"
#include "pqmesh/quality.hpp"

namespace pqmesh {
namespace {

std::int64_t total(const Histogram& h) { return std::accumulate(h.counts.begin(), h.counts.end(), std::int64_t{0}); }

std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// Three triangles sharing no vertices, with the values of
// triangle_quality_test.cpp: 0 equilateral (angles 60, aspect 2), 1 right
// isosceles (45/90, aspect 1 + sqrt2 ~ 2.414), 2 obtuse (26.57/126.87,
// aspect 2 + sqrt5 ~ 4.236, area 2).
TriMesh2 three_triangles() {
  TriMesh2 m;
  m.vertices = {{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}, {10, 0}, {11, 0}, {10, 1}, {20, 0}, {24, 0}, {22, 1}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  return m;
}

TEST(QualityReport, TriangleMeshStatisticsAndArgs) {
  const TriMesh2 m = three_triangles();
  const std::vector<TriQuality> per = element_quality(m);
  ASSERT_EQ(per.size(), 3u);
  EXPECT_NEAR(per[2].aspect_ratio, 2 + std::sqrt(5.0), 1e-12);

  const QualityReport r = quality_report(m);
  EXPECT_EQ(r.dimension, 2);
  EXPECT_EQ(r.elements, 3);
  EXPECT_EQ(r.degenerate, 0);
  EXPECT_EQ(r.inverted, 0);
  EXPECT_EQ(r.min_angle.argmin, 2);
  EXPECT_EQ(r.min_angle.argmax, 0);
  EXPECT_NEAR(r.min_angle.min, std::atan(0.5) * 180 / std::acos(-1.0), 1e-10);
  EXPECT_NEAR(r.min_angle.mean, (60 + 45 + std::atan(0.5) * 180 / std::acos(-1.0)) / 3, 1e-10);
  EXPECT_EQ(r.max_angle.argmax, 2);
  EXPECT_EQ(r.aspect_ratio.argmin, 0);
  EXPECT_EQ(r.aspect_ratio.argmax, 2);
  EXPECT_NEAR(r.aspect_ratio.max, 2 + std::sqrt(5.0), 1e-12);
  EXPECT_EQ(r.size.argmax, 2);
  // Areas sqrt3/4 + 1/2 + 2.
  EXPECT_NEAR(r.total_size, std::sqrt(3.0) / 4 + 2.5, 1e-12);

  // Histograms: every element counted once, in the bin derived by hand.
  EXPECT_EQ(total(r.min_angle_hist), 3);
  EXPECT_EQ(total(r.max_angle_hist), 3);
  EXPECT_EQ(total(r.aspect_hist), 3);
  ASSERT_EQ(r.min_angle_hist.counts.size(), 18u);  // [0, 90] in 5-degree bins
  EXPECT_EQ(r.min_angle_hist.counts[5], 1);        // 26.57 in [25, 30)
  EXPECT_EQ(r.min_angle_hist.counts[9], 1);        // 45 in [45, 50)
  // 60 in [60, 65), or [55, 60) if it rounds below 60; the two bins hold one.
  EXPECT_EQ(r.min_angle_hist.counts[11] + r.min_angle_hist.counts[12], 1);
  ASSERT_EQ(r.max_angle_hist.counts.size(), 36u);
  EXPECT_EQ(r.max_angle_hist.counts[25], 1);  // 126.87 in [125, 130)
  // Aspect edges 2 x {1, 1.1, 1.25, 1.5, 2, 3, 5, 10, 100, inf}
  // = {2, 2.2, 2.5, 3, 4, 6, 10, 20, 200, inf}.
  ASSERT_EQ(r.aspect_hist.edges.size(), 10u);
  EXPECT_EQ(r.aspect_hist.edges[1], 2.2);
  EXPECT_TRUE(std::isinf(r.aspect_hist.edges.back()));
  EXPECT_EQ(r.aspect_hist.counts[0], 1);  // 2 (or a hair below: clamped)
  EXPECT_EQ(r.aspect_hist.counts[1], 1);  // 2.414 in [2.2, 2.5)
  EXPECT_EQ(r.aspect_hist.counts[4], 1);  // 4.236 in [4, 6)

  // The span overload gives the same report as the mesh overload.
  const QualityReport r2 = quality_report(std::span<const TriQuality>(per));
  EXPECT_EQ(r2.to_text(), r.to_text());
}

TEST(QualityReport, DegenerateAndInvertedCounted) {
  TriMesh2 m = three_triangles();
  m.vertices.push_back({30, 0});
  m.vertices.push_back({31, 0});
  m.vertices.push_back({32, 0});
  m.triangles.push_back({9, 10, 11});  // collinear: degenerate, element 3
  m.triangles.push_back({0, 2, 1});    // clockwise: inverted, element 4
  const QualityReport r = quality_report(m);
  EXPECT_EQ(r.elements, 5);
  EXPECT_EQ(r.degenerate, 1);
  EXPECT_EQ(r.inverted, 1);
  EXPECT_EQ(r.aspect_ratio.argmax, 3);
  EXPECT_TRUE(std::isinf(r.aspect_ratio.max));
  EXPECT_TRUE(std::isinf(r.aspect_ratio.mean));
  EXPECT_EQ(r.min_angle.argmin, 3);  // 0 degrees
  EXPECT_EQ(r.size.argmin, 4);       // -sqrt3/4
  EXPECT_EQ(r.aspect_hist.counts.back(), 1);    // +infinity in the open last bin
  EXPECT_EQ(r.max_angle_hist.counts.back(), 1);  // exactly 180 in the closed last bin
  EXPECT_EQ(total(r.aspect_hist), 5);
  EXPECT_EQ(total(r.min_angle_hist), 5);
  EXPECT_EQ(total(r.max_angle_hist), 5);
}

// Tetrahedra: 0 regular (min dihedral 70.53), 1 sliver h = 0.01 (min
// dihedral ~1.15, aspect ~141), 2 corner (54.74 / 90), 3 needle (45.17 /
// 171.9, aspect 34.18), 4 an identical copy of the sliver.
TetMesh3 five_tets() {
  TetMesh3 m;
  m.vertices = {{1, 1, 1},  {1, -1, -1}, {-1, -1, 1}, {-1, 1, -1},                   // regular
                {0, 0, 0},  {1, 1, 0},   {0, 1, 0.01}, {1, 0, 0.01},                 // sliver
                {5, 0, 0},  {6, 0, 0},   {5, 1, 0},    {5, 0, 1},                    // corner
                {-10, 5, 5}, {10, 5, 5}, {0, 6, 5},    {0, 5, 6}};                   // needle
  m.tetrahedra = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}, {12, 13, 14, 15}, {4, 5, 6, 7}};
  return m;
}

TEST(QualityReport, TetMeshArgsFirstOfTies) {
  const QualityReport r = quality_report(five_tets());
  EXPECT_EQ(r.dimension, 3);
  EXPECT_EQ(r.elements, 5);
  EXPECT_EQ(r.min_angle.argmin, 1);  // the sliver; its copy (4) ties and loses
  EXPECT_EQ(r.max_angle.argmax, 1);
  EXPECT_EQ(r.aspect_ratio.argmax, 1);
  EXPECT_EQ(r.aspect_ratio.argmin, 0);
  EXPECT_NEAR(r.aspect_ratio.min, 3.0, 1e-12);
  EXPECT_EQ(r.min_angle.argmax, 0);  // regular: arccos(1/3) ~ 70.53
  EXPECT_EQ(r.radius_edge.argmax, 3);  // needle: sqrt2500.25
  EXPECT_NEAR(r.radius_edge.max, std::sqrt(2500.25), 1e-10);
  // Volumes 8/3 + 0.01/3 + 1/6 + 10/3 + 0.01/3.
  EXPECT_NEAR(r.total_size, 8.0 / 3 + 0.02 / 3 + 1.0 / 6 + 10.0 / 3, 1e-12);
  ASSERT_EQ(r.min_angle_hist.counts.size(), 36u);  // dihedrals over [0, 180]
  EXPECT_EQ(r.min_angle_hist.counts[0], 2);         // two slivers in [0, 5)
  EXPECT_EQ(r.min_angle_hist.counts[9], 1);         // needle 45.17 in [45, 50)
  EXPECT_EQ(r.min_angle_hist.counts[10], 1);        // corner 54.74 in [50, 55)
  EXPECT_EQ(r.min_angle_hist.counts[14], 1);        // regular 70.53 in [70, 75)
  EXPECT_EQ(total(r.min_angle_hist), 5);
  EXPECT_EQ(total(r.max_angle_hist), 5);
  EXPECT_EQ(total(r.aspect_hist), 5);
  // Aspect edges 3 x {1, 1.1, 1.25, 1.5, 2, 3, 5, 10, 100, inf}: regular 3 in
  // bin 0, corner 3.86 in [3.75, 4.5) = bin 2, needle 34.18 in [30, 300) = bin 7,
  // slivers 141.4 also bin 7.
  EXPECT_EQ(r.aspect_hist.counts[0], 1);
  EXPECT_EQ(r.aspect_hist.counts[2], 1);
  EXPECT_EQ(r.aspect_hist.counts[7], 3);
}

TEST(QualityReport, EmptyMesh) {
  const QualityReport r = quality_report(TetMesh3{});
  EXPECT_EQ(r.elements, 0);
  EXPECT_EQ(r.aspect_ratio.argmin, -1);
  EXPECT_EQ(r.aspect_ratio.mean, 0.0);
  EXPECT_EQ(total(r.aspect_hist), 0);
  const std::string text = r.to_text();
  EXPECT_NE(text.find("quality of 0 tetrahedra"), std::string::npos);
  EXPECT_NE(text.find("(no elements)"), std::string::npos);
  EXPECT_TRUE(element_quality(TriMesh2{}).empty());
}

TEST(QualityReport, BadVertexIndexThrowsWithIds) {
  TetMesh3 m = five_tets();
  m.tetrahedra[2][3] = 16;  // one past the last vertex
  try {
    (void)element_quality(m);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.code(), ErrorCode::IndexOutOfRange);
    EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{2, 16}));
  }
  EXPECT_THROW((void)quality_report(m), InvalidInput);
  TriMesh2 t = three_triangles();
  t.triangles[0][0] = -1;
  EXPECT_THROW((void)quality_report(t), InvalidInput);
}

TEST(QualityReport, TextReport) {
  const std::string text = quality_report(three_triangles()).to_text();
  EXPECT_NE(text.find("quality of 3 triangles (degenerate 0, inverted 0)"), std::string::npos);
  EXPECT_NE(text.find("min angle (deg)"), std::string::npos);
  EXPECT_NE(text.find("aspect ratio"), std::string::npos);
  EXPECT_NE(text.find("radius-edge ratio"), std::string::npos);
  // The min-angle histogram runs from the first to the last nonempty bin,
  // [25, 30) .. [60, 65) or [55, 60): the [0, 5) bin is trimmed, [25, 30) shows
  // its one element with the full 40-character bar (the peak count is 1).
  EXPECT_EQ(text.find("[     0,      5)"), std::string::npos);
  EXPECT_NE(text.find("[    25,     30)          1 " + std::string(40, '#') + "\n"), std::string::npos);
  // The aspect histogram's open last bin is not drawn (empty, trimmed); the
  // max-angle histogram's last drawn bin is [125, 130).
  EXPECT_NE(text.find("[   125,    130)"), std::string::npos);
  EXPECT_EQ(count_of(text, "(deg):\n"), 2u);
  // Deterministic.
  EXPECT_EQ(text, quality_report(three_triangles()).to_text());
}

TEST(HistogramSvg, WellFormedAndEscaped) {
  const QualityReport r = quality_report(five_tets());
  const std::string svg = histogram_svg(r.min_angle_hist, "min dihedral <5 tets> & co");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_NE(svg.find("min dihedral &lt;5 tets&gt; &amp; co"), std::string::npos);
  EXPECT_EQ(svg.find("<5 tets>"), std::string::npos);
  // One background rect plus one bar per bin.
  EXPECT_EQ(count_of(svg, "<rect "), 1 + r.min_angle_hist.counts.size());
  EXPECT_NE(svg.find("<title>[0, 5): 2</title>"), std::string::npos);
  EXPECT_EQ(svg, histogram_svg(r.min_angle_hist, "min dihedral <5 tets> & co"));
  // The aspect histogram's last edge is infinite: printed as "inf", no NaN.
  const std::string aspect = histogram_svg(r.aspect_hist, "aspect");
  EXPECT_NE(aspect.find("inf): 0"), std::string::npos);
  EXPECT_EQ(aspect.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace pqmesh
