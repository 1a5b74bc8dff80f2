// TetGen .poly/.smesh reading, including facets made of several polygons.
// Expected values are read off the fixtures (line numbers counted by hand).
#include <gtest/gtest.h>

#include "io_read_helpers.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh {
namespace {

using test::fixture;

TEST(ReadTetgen, CubePoly) {
  ReadReport report;
  const Plc3 p = read_plc(fixture("cube.poly"), {}, &report);
  EXPECT_EQ(p.source.first_id, 1);
  ASSERT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.vertices[6], (Vec3{1, 1, 1}));
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{1, 1, 1, 1, 2, 2, 2, 2}));
  ASSERT_EQ(p.facets.size(), 6u);
  // Facet 1: "4 1 4 3 2" -> indices 0 3 2 1, marker 11 (line 12 holds "1 0 11").
  ASSERT_EQ(p.facets[0].loops.size(), 1u);
  EXPECT_EQ(p.facets[0].loops[0], (std::vector<int>{0, 3, 2, 1}));
  EXPECT_EQ(p.facets[0].marker, 11);
  EXPECT_EQ(p.facets[5].marker, 16);
  EXPECT_EQ(p.source.element_line, (std::vector<int>{12, 14, 16, 18, 20, 22}));
  EXPECT_TRUE(p.holes.empty());
  ASSERT_EQ(p.regions.size(), 1u);
  EXPECT_EQ(p.regions[0].point, (Vec3{0.5, 0.5, 0.5}));
  EXPECT_EQ(p.regions[0].attribute, 3);
  EXPECT_EQ(p.regions[0].max_volume, 0.125);
  EXPECT_EQ(report.input_polygons, 6);
  EXPECT_EQ(report.facets, 6);
}

TEST(ReadTetgen, SmeshWithNodeFileZeroBased) {
  const Plc3 p = read_plc(fixture("cube_s.smesh"));
  EXPECT_EQ(p.source.first_id, 0);
  ASSERT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.vertices[2], (Vec3{2, 2, 0}));
  EXPECT_TRUE(p.vertex_markers.empty());
  ASSERT_EQ(p.facets.size(), 6u);
  EXPECT_EQ(p.facets[1].loops[0], (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(p.facets[1].marker, 22);
  EXPECT_EQ(p.source.element_line[0], 4);
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_EQ(p.holes[0], (Vec3{5, 5, 5}));
}

TEST(ReadTetgen, MultiPolygonFacets) {
  const Plc3 p = read_plc(fixture("facets.poly"));
  ASSERT_EQ(p.facets.size(), 5u);
  // Facet 1: outer square with a hole point inside the inner square -> one
  // facet with one hole loop.
  ASSERT_EQ(p.facets[0].loops.size(), 2u);
  EXPECT_EQ(p.facets[0].loops[0], (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(p.facets[0].loops[1], (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(p.facets[0].marker, 5);
  // Facet 2: the same polygons without a hole point: the ring and the inner
  // square, both marker 6.
  ASSERT_EQ(p.facets[1].loops.size(), 2u);
  EXPECT_EQ(p.facets[1].loops[1], (std::vector<int>{4, 5, 6, 7}));
  ASSERT_EQ(p.facets[2].loops.size(), 1u);
  EXPECT_EQ(p.facets[2].loops[0], (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(p.facets[2].marker, 6);
  // Facet 3: two side-by-side quadrilaterals tile it -> two facets.
  EXPECT_EQ(p.facets[3].loops, (std::vector<std::vector<int>>{{1, 8, 11, 2}}));
  EXPECT_EQ(p.facets[4].loops, (std::vector<std::vector<int>>{{8, 9, 10, 11}}));
  EXPECT_EQ(p.facets[4].marker, 7);
  EXPECT_EQ(p.source.element_line, (std::vector<int>{16, 20, 20, 23, 23}));
}

TEST(ReadTetgen, SegmentInsideFacetIsUnsupported) {
  test::expect_parse_error([] { read_plc(fixture("segment_in_facet.poly")); }, {ErrorCode::Unsupported, 9, {1}},
                           fixture("segment_in_facet.poly"));
}

}  // namespace
}  // namespace pqmesh
