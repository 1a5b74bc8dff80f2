// make_domain(Pslg2) and locate(Domain2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh {
namespace {

// Closed polygon through the given points (segments k -> k+1), appended.
void add_loop(Pslg2& g, const std::vector<Vec2>& pts) {
  const int o = static_cast<int>(g.vertices.size()), n = static_cast<int>(pts.size());
  g.vertices.insert(g.vertices.end(), pts.begin(), pts.end());
  for (int k = 0; k < n; ++k) g.segments.push_back({o + k, o + (k + 1) % n});
}

// 2 x 2 square (vertices 0-3, segments 0-3) with a 1 x 1 hole (4-7, 4-7).
Pslg2 square_with_hole(bool outer_ccw = true, bool hole_ccw = true) {
  Pslg2 g;
  std::vector<Vec2> outer = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  std::vector<Vec2> hole = {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
  if (!outer_ccw) std::reverse(outer.begin(), outer.end());
  if (!hole_ccw) std::reverse(hole.begin(), hole.end());
  add_loop(g, outer);
  add_loop(g, hole);
  return g;
}

DomainError expect_error(const Pslg2& g, ErrorCode code) {
  try {
    make_domain(g);
  } catch (const DomainError& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    return e;
  }
  ADD_FAILURE() << "no DomainError, expected " << to_string(code);
  return DomainError(code, "none");
}

// loop_segments[i][k] joins loops[i][k] and loops[i][k+1].
void expect_consistent(const Domain2& d) {
  for (std::size_t i = 0; i < d.loops.size(); ++i) {
    const auto& l = d.loops[i];
    ASSERT_EQ(l.size(), d.loop_segments[i].size());
    for (std::size_t k = 0; k < l.size(); ++k) {
      const auto s = d.pslg.segments[d.loop_segments[i][k]];
      const int a = l[k], b = l[(k + 1) % l.size()];
      EXPECT_TRUE((s[0] == a && s[1] == b) || (s[0] == b && s[1] == a)) << i << " " << k;
    }
  }
}

TEST(Domain2, SquareWithHole) {
  for (bool oc : {true, false})
    for (bool hc : {true, false}) {
      const Domain2 d = make_domain(square_with_hole(oc, hc));
      ASSERT_EQ(d.loops.size(), 2u);
      EXPECT_EQ(d.area, 3.0);  // 4 - 1, exact for these dyadic coordinates
      // Outer counter-clockwise: from vertex 0 = (0,0) the next vertex is (2,0).
      const auto& outer = d.loops[0];
      const auto it = std::find(outer.begin(), outer.end(), oc ? 0 : 3);
      ASSERT_NE(it, outer.end());
      const Vec2 next = d.pslg.vertices[outer[(it - outer.begin() + 1) % 4]];
      EXPECT_EQ(next, (Vec2{2, 0}));
      // The hole clockwise: after (0.5, 0.5) comes (0.5, 1.5).
      const auto& hole = d.loops[1];
      const auto h = std::find_if(hole.begin(), hole.end(), [&](int v) { return d.pslg.vertices[v] == Vec2{0.5, 0.5}; });
      ASSERT_NE(h, hole.end());
      EXPECT_EQ(d.pslg.vertices[hole[(h - hole.begin() + 1) % 4]], (Vec2{0.5, 1.5}));
      expect_consistent(d);
      EXPECT_EQ(d.bbox_min, (Vec2{0, 0}));
      EXPECT_EQ(d.bbox_max, (Vec2{2, 2}));
    }
}

TEST(Domain2, HoleListedFirst) {
  Pslg2 g;
  add_loop(g, {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}});
  add_loop(g, {{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const Domain2 d = make_domain(g);
  EXPECT_EQ(d.area, 3.0);
  EXPECT_GE(d.loops[0][0], 4);  // the outer loop is the second one given
}

TEST(Domain2, Locate) {
  const Domain2 d = make_domain(square_with_hole());
  EXPECT_EQ(locate(d, {0.25, 0.25}), Location::Inside);
  EXPECT_EQ(locate(d, {1, 1}), Location::Outside);       // in the hole
  EXPECT_EQ(locate(d, {3, 1}), Location::Outside);
  EXPECT_EQ(locate(d, {1, 0}), Location::Boundary);      // on a segment
  EXPECT_EQ(locate(d, {0.5, 0.5}), Location::Boundary);  // hole vertex
  EXPECT_EQ(locate(d, {2, 2}), Location::Boundary);
  // Rays (towards +x) through vertices: y = 0.5 passes the hole's corners.
  EXPECT_EQ(locate(d, {0.25, 0.5}), Location::Inside);
  EXPECT_EQ(locate(d, {0.25, 1.5}), Location::Inside);
  EXPECT_EQ(locate(d, {1.75, 1.5}), Location::Inside);
}

TEST(Domain2, LocateDiamondGrid) {
  // Diamond |x| + |y| <= 2 with a diamond hole |x| + |y| <= 1: exhaustive
  // dyadic grid against the analytic answer (many rays through vertices).
  Pslg2 g;
  add_loop(g, {{2, 0}, {0, 2}, {-2, 0}, {0, -2}});
  add_loop(g, {{1, 0}, {0, 1}, {-1, 0}, {0, -1}});
  const Domain2 d = make_domain(g);
  for (double x = -2.5; x <= 2.5; x += 0.25)
    for (double y = -2.5; y <= 2.5; y += 0.25) {
      const double r = std::abs(x) + std::abs(y);
      const Location want = (r == 1 || r == 2) ? Location::Boundary
                            : (r > 1 && r < 2) ? Location::Inside
                                               : Location::Outside;
      ASSERT_EQ(locate(d, {x, y}), want) << x << " " << y;
    }
}

TEST(Domain2Errors, Codes) {
  expect_error(Pslg2{}, ErrorCode::EmptyDomain);
  {
    Pslg2 g = square_with_hole();
    g.vertices[2].x = std::numeric_limits<double>::infinity();
    EXPECT_EQ(expect_error(g, ErrorCode::NonFinite).ids(), (std::vector<std::int64_t>{2}));
  }
  {
    Pslg2 g = square_with_hole();
    g.segments[5][1] = 42;
    EXPECT_EQ(expect_error(g, ErrorCode::IndexOutOfRange).ids(), (std::vector<std::int64_t>{5}));
  }
  {
    Pslg2 g = square_with_hole();
    g.segments.push_back({1, 1});
    EXPECT_EQ(expect_error(g, ErrorCode::DegenerateFacet).ids(), (std::vector<std::int64_t>{8}));
  }
  {
    Pslg2 g = square_with_hole();
    g.vertices[6] = g.vertices[2];  // hole vertex onto an outer corner
    g.source.first_id = 1;
    g.source.path = "sq.poly";
    g.source.vertex_line = {3, 4, 5, 6, 7, 8, 9, 10};
    const auto e = expect_error(g, ErrorCode::DuplicateVertex);
    EXPECT_EQ(e.ids(), (std::vector<std::int64_t>{3, 7}));
    EXPECT_EQ(e.line(), 5);
  }
  {
    Pslg2 g = square_with_hole();
    g.segments.push_back({1, 0});  // same as segment 0
    EXPECT_EQ(expect_error(g, ErrorCode::InvalidPolygon).ids(), (std::vector<std::int64_t>{0, 8}));
  }
  {
    Pslg2 g = square_with_hole();
    g.vertices.push_back({5, 5});  // unused
    EXPECT_EQ(expect_error(g, ErrorCode::InvalidPolygon).ids(), (std::vector<std::int64_t>{8}));
  }
  {
    Pslg2 g = square_with_hole();
    g.vertices.push_back({3, 3});
    g.segments.push_back({2, 8});  // dangling segment: vertex 2 has 3 segments, 8 has 1
    EXPECT_EQ(expect_error(g, ErrorCode::InvalidPolygon).ids(), (std::vector<std::int64_t>{2, 8}));
  }
}

TEST(Domain2Errors, CrossingAndTouching) {
  {
    Pslg2 g;
    add_loop(g, {{0, 0}, {2, 2}, {2, 0}, {0, 2}});  // bowtie: segments 0 and 2 cross
    EXPECT_EQ(expect_error(g, ErrorCode::SelfIntersectingFacet).ids(), (std::vector<std::int64_t>{0, 2}));
  }
  {
    Pslg2 g;
    add_loop(g, {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    add_loop(g, {{2, 0}, {3, 1}, {1, 1}});  // hole vertex on outer segment 0
    EXPECT_EQ(expect_error(g, ErrorCode::SelfIntersectingFacet).ids(), (std::vector<std::int64_t>{0, 4}));
  }
}

TEST(Domain2Errors, Disconnected) {
  {
    Pslg2 g;
    add_loop(g, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    add_loop(g, {{2, 0}, {3, 0}, {3, 1}, {2, 1}});
    EXPECT_EQ(expect_error(g, ErrorCode::Disconnected).ids(), (std::vector<std::int64_t>{0, 4}));
  }
  {
    Pslg2 g;
    add_loop(g, {{0, 0}, {8, 0}, {8, 8}, {0, 8}});
    add_loop(g, {{2, 2}, {6, 2}, {6, 6}, {2, 6}});  // hole
    add_loop(g, {{3, 3}, {5, 3}, {5, 5}, {3, 5}});  // island in the hole
    EXPECT_EQ(expect_error(g, ErrorCode::Disconnected).ids(), (std::vector<std::int64_t>{8, 4}));
  }
}

TEST(Domain2Errors, HolePoints) {
  Pslg2 g = square_with_hole();
  g.holes = {{1, 1}, {5, 5}};  // in the hole, outside: fine
  EXPECT_NO_THROW(make_domain(g));
  g.holes.push_back({0.25, 1});
  EXPECT_EQ(expect_error(g, ErrorCode::Unsupported).ids(), (std::vector<std::int64_t>{2}));
}

}  // namespace
}  // namespace pqmesh
