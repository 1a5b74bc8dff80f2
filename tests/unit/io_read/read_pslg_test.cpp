// Triangle .poly reading: counts, coordinates, markers, holes, regions, 0- and
// 1-based ids, the .node companion, and domain_dimension. Expected values are
// read off the hand-written fixtures in fixtures/.
#include <gtest/gtest.h>

#include "io_read_helpers.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh {
namespace {

using test::fixture;

TEST(ReadPslg, SquareWithHoleOneBased) {
  const Pslg2 p = read_pslg(fixture("square_hole.poly"));
  EXPECT_EQ(p.source.first_id, 1);
  ASSERT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.vertices[1], (Vec2{3, 0}));
  EXPECT_EQ(p.vertices[6], (Vec2{2, 2}));
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{1, 1, 1, 1, 2, 2, 2, 2}));
  ASSERT_EQ(p.segments.size(), 8u);
  // Segment 4 (file ids 4 1) -> indices 3 0; segment 8 (8 5) -> 7 4.
  EXPECT_EQ(p.segments[3], (std::array<int, 2>{3, 0}));
  EXPECT_EQ(p.segments[7], (std::array<int, 2>{7, 4}));
  EXPECT_EQ(p.segment_markers, (std::vector<int>{10, 10, 10, 10, 20, 20, 20, 20}));
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_EQ(p.holes[0], (Vec2{1.5, 1.5}));
  ASSERT_EQ(p.regions.size(), 1u);
  EXPECT_EQ(p.regions[0].point, (Vec2{0.5, 0.5}));
  EXPECT_EQ(p.regions[0].attribute, 4);
  EXPECT_EQ(p.regions[0].max_area, 0.25);
  // Line 3 holds vertex 1; the segment section starts on line 13 (blank line 11, comment line 12).
  EXPECT_EQ(p.source.line_of_vertex(0), 3);
  EXPECT_EQ(p.source.line_of_vertex(7), 10);
  EXPECT_EQ(p.source.line_of_element(0), 14);
  EXPECT_EQ(p.source.line_of_element(7), 21);
}

TEST(ReadPslg, ZeroBasedWithAttributesAndNoHoleSection) {
  const Pslg2 p = read_pslg(fixture("triangle0.poly"));
  EXPECT_EQ(p.source.first_id, 0);
  ASSERT_EQ(p.vertices.size(), 3u);
  EXPECT_EQ(p.vertices[2], (Vec2{0, 3}));
  EXPECT_TRUE(p.vertex_markers.empty());
  EXPECT_TRUE(p.segment_markers.empty());
  ASSERT_EQ(p.segments.size(), 3u);
  EXPECT_EQ(p.segments[2], (std::array<int, 2>{2, 0}));
  EXPECT_TRUE(p.holes.empty());
  EXPECT_EQ(p.source.line_of_vertex(0), 4);
}

TEST(ReadPslg, NodeCompanion) {
  const Pslg2 p = read_pslg(fixture("companion.poly"));
  EXPECT_EQ(p.source.first_id, 1);
  ASSERT_EQ(p.vertices.size(), 3u);
  EXPECT_EQ(p.vertices[1], (Vec2{1, 0}));
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{5, 6, 7}));
  ASSERT_EQ(p.segments.size(), 3u);
  EXPECT_EQ(p.segments[2], (std::array<int, 2>{2, 0}));
  EXPECT_EQ(p.source.line_of_vertex(0), 3);  // line in companion.node
}

TEST(ReadPslg, DomainDimension) {
  EXPECT_EQ(domain_dimension(fixture("square_hole.poly")), 2);
  EXPECT_EQ(domain_dimension(fixture("companion.poly")), 2);  // from the .node header
  EXPECT_EQ(domain_dimension(fixture("cube.poly")), 3);
  EXPECT_EQ(domain_dimension(fixture("cube_s.smesh")), 3);
  EXPECT_EQ(domain_dimension(fixture("cube_ascii.stl")), 3);
  EXPECT_EQ(domain_dimension("whatever.off"), 3);
  EXPECT_THROW(domain_dimension("shape.xyz"), ParseError);
}

TEST(ReadPslg, WrongDimensionForReader) {
  test::expect_parse_error([] { read_pslg(fixture("cube.poly")); }, {ErrorCode::WrongCount, 1, {}},
                           fixture("cube.poly"));
  test::expect_parse_error([] { read_plc(fixture("square_hole.poly")); }, {ErrorCode::WrongCount, 1, {}},
                           fixture("square_hole.poly"));
}

}  // namespace
}  // namespace pqmesh
