// Soup merging (src/plc/soup_merge) on hand-built soups. Expected loops are
// derived from the drawings in the comments.
#include "plc/soup_merge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "io_read_helpers.hpp"
#include "predicates/predicates.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh::detail {
namespace {

void add(PolygonSoup& s, std::vector<int> poly, int marker = 0) {
  s.indices.insert(s.indices.end(), poly.begin(), poly.end());
  s.offsets.push_back(static_cast<int>(s.indices.size()));
  s.markers.push_back(marker);
}

// Is `loop` a cyclic rotation of `want`?
bool same_cycle(const std::vector<int>& loop, const std::vector<int>& want) {
  if (loop.size() != want.size()) return false;
  for (std::size_t r = 0; r < loop.size(); ++r) {
    bool ok = true;
    for (std::size_t i = 0; i < loop.size() && ok; ++i) ok = loop[(r + i) % loop.size()] == want[i];
    if (ok) return true;
  }
  return false;
}

// L shape in z = 0 (ids 0..5 counter-clockwise):
//   5---4
//   |   |
//   |   3---2
//   |       |
//   0-------1
// split into 4 triangles fanned from vertex 0 (no interior vertex).
TEST(SoupMerge, LShapeBecomesOneSixVertexFacet) {
  PolygonSoup s;
  s.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  add(s, {0, 1, 2});
  add(s, {0, 2, 3});
  add(s, {0, 3, 4});
  add(s, {0, 4, 5});
  const SoupMergeResult r = merge_soup(s, 0);
  ASSERT_EQ(r.facets.size(), 1u);
  ASSERT_EQ(r.facets[0].loops.size(), 1u);
  EXPECT_TRUE(same_cycle(r.facets[0].loops[0], {0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(r.merged_exact, 3);
  EXPECT_EQ(r.first_polygon, (std::vector<int>{0}));
}

// A 3x3 square (outer ids 0..3) with a 1x1 square hole (inner ids 4..7),
// the ring split into 8 triangles, two per side trapezoid.
TEST(SoupMerge, AnnulusBecomesFacetWithHole) {
  PolygonSoup s;
  s.vertices = {{0, 0, 5}, {3, 0, 5}, {3, 3, 5}, {0, 3, 5}, {1, 1, 5}, {2, 1, 5}, {2, 2, 5}, {1, 2, 5}};
  for (int k = 0; k < 4; ++k) {
    const int o0 = k, o1 = (k + 1) % 4, i0 = 4 + k, i1 = 4 + (k + 1) % 4;
    add(s, {o0, o1, i1});
    add(s, {o0, i1, i0});
  }
  const SoupMergeResult r = merge_soup(s, 0);
  ASSERT_EQ(r.facets.size(), 1u);
  ASSERT_EQ(r.facets[0].loops.size(), 2u);
  EXPECT_TRUE(same_cycle(r.facets[0].loops[0], {0, 1, 2, 3}));  // counter-clockwise like the triangles
  EXPECT_TRUE(same_cycle(r.facets[0].loops[1], {7, 6, 5, 4}));  // the hole turns the other way
  EXPECT_EQ(r.merged_exact, 7);
}

// Unit squares of a 3x3 grid except the centre (1,1) and the corner (2,2):
// the hole (the centre square) touches the outer boundary at grid point (2,2).
// The pinch must be split into an outer loop of 12 boundary grid points and a
// hole loop of 4 that share that vertex.
TEST(SoupMerge, PinchedBoundarySplitsIntoOuterAndHole) {
  PolygonSoup s;
  auto id = [](int x, int y) { return 4 * y + x; };
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) s.vertices.push_back({double(x), double(y), 0});
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) {
      if ((x == 1 && y == 1) || (x == 2 && y == 2)) continue;
      add(s, {id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      add(s, {id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  const SoupMergeResult r = merge_soup(s, 0);
  ASSERT_EQ(r.facets.size(), 1u);
  const auto& loops = r.facets[0].loops;
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_TRUE(same_cycle(loops[0], {id(0, 0), id(1, 0), id(2, 0), id(3, 0), id(3, 1), id(3, 2), id(2, 2), id(2, 3),
                                    id(1, 3), id(0, 3), id(0, 2), id(0, 1)}));
  EXPECT_TRUE(same_cycle(loops[1], {id(1, 1), id(1, 2), id(2, 2), id(2, 1)}));
}

TEST(SoupMerge, DifferentMarkersOrFacingDoNotMerge) {
  PolygonSoup s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  add(s, {0, 1, 2}, 1);
  add(s, {0, 2, 3}, 2);
  EXPECT_EQ(merge_soup(s, 0).facets.size(), 2u);
  // Same marker but the second triangle folded back over the first: it shares
  // edge 0-2 in the opposite direction yet faces the other way.
  PolygonSoup t;
  t.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}};
  add(t, {0, 1, 2});
  add(t, {2, 0, 3});  // (1,1) (0,0) (2,0): clockwise seen from +z
  EXPECT_EQ(merge_soup(t, 0).facets.size(), 2u);
}

// Two triangles meeting at edge (1,0,0)-(0,1,0) with a crease: the second
// lifts (1,1) to height h = 1/128, so its normal (-h, -h, 1) makes an angle
// atan(h sqrt 2) = 0.633 degrees with +z.
PolygonSoup crease(double h) {
  PolygonSoup s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, h}, {0, 1, 0}};
  add(s, {0, 1, 3});
  add(s, {1, 2, 3});
  return s;
}

TEST(SoupMerge, CreaseMergesOnlyWithinAngle) {
  const double h = 1.0 / 128;
  PolygonSoup a = crease(h);
  const SoupMergeResult exact = merge_soup(a, 0);
  EXPECT_EQ(exact.facets.size(), 2u);
  PolygonSoup b = crease(h);
  const SoupMergeResult narrow = merge_soup(b, 0.5);
  EXPECT_EQ(narrow.facets.size(), 2u);
  EXPECT_EQ(narrow.merged_near, 0);
  PolygonSoup c = crease(h);
  const SoupMergeResult wide = merge_soup(c, 1.0);
  ASSERT_EQ(wide.facets.size(), 1u);
  EXPECT_EQ(wide.merged_near, 1);
  EXPECT_EQ(wide.merged_exact, 0);
  EXPECT_TRUE(same_cycle(wide.facets[0].loops[0], {0, 1, 2, 3}));
  // No other polygon uses them, so the four vertices were snapped onto one
  // plane: now exactly coplanar, and each moved by much less than h.
  const auto& V = c.vertices;
  EXPECT_EQ(orient3d(V[0], V[1], V[2], V[3]), Sign::Zero);
  const Vec3 orig[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, h}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) EXPECT_LT(norm(V[i] - orig[i]), h) << i;
}

TEST(SoupMerge, CreaseWithSharedVertexIsNotMerged) {
  const double h = 1.0 / 128;
  PolygonSoup s = crease(h);
  s.vertices.push_back({2, 0, 0});
  add(s, {2, 1, 4}, 7);  // another facet uses (1,0,0) and (1,1,h): they cannot move
  const SoupMergeResult r = merge_soup(s, 1.0);
  EXPECT_EQ(r.facets.size(), 3u);
  EXPECT_EQ(r.merged_near, 0);
  EXPECT_EQ(s.vertices[2], (Vec3{1, 1, h}));
}

// A 2x2 square in z = 0 fanned around a centre vertex lifted to z = 1/256:
// the four triangles are pairwise slightly creased, but the square's corners
// (also used by a neighbouring facet) are coplanar, so the near merge keeps
// them in place and the centre vertex drops out of the facet.
TEST(SoupMerge, NearMergeWithCoplanarBoundaryMovesNothing) {
  PolygonSoup s;
  s.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 1.0 / 256}, {1, -1, -1}};
  add(s, {0, 1, 4});
  add(s, {1, 2, 4});
  add(s, {2, 3, 4});
  add(s, {3, 0, 4});
  add(s, {1, 0, 5}, 3);  // a neighbour below edge 0-1
  const std::vector<Vec3> before = s.vertices;
  const SoupMergeResult r = merge_soup(s, 2.0);
  ASSERT_EQ(r.facets.size(), 2u);
  EXPECT_TRUE(same_cycle(r.facets[0].loops[0], {0, 1, 2, 3}));
  EXPECT_EQ(r.merged_near, 3);
  EXPECT_EQ(s.vertices, before);
}

// Binary STL of the box [0,n]^3 whose faces are n x n grids of unit squares,
// two triangles each (12 n^2 triangles; n = 91 gives 99,372).
std::string gridded_box_stl(int n) {
  std::vector<float> tris;
  auto push = [&](const float* a, const float* b, const float* c) {
    const float zero[3] = {0, 0, 0};
    tris.insert(tris.end(), zero, zero + 3);
    tris.insert(tris.end(), a, a + 3);
    tris.insert(tris.end(), b, b + 3);
    tris.insert(tris.end(), c, c + 3);
  };
  // Face with fixed axis w at value f; (u, v) the other axes in cyclic order,
  // so (u, v, w) is right-handed and the grid turns counter-clockwise about +w.
  for (int w = 0; w < 3; ++w)
    for (int side = 0; side < 2; ++side) {
      const int u = (w + 1) % 3, v = (w + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          float p[4][3];
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            p[k][w] = float(side * n);
            p[k][u] = float(i + du[k]);
            p[k][v] = float(j + dv[k]);
          }
          if (side == 1) {
            push(p[0], p[1], p[2]);
            push(p[0], p[2], p[3]);
          } else {  // outward is -w: reverse
            push(p[0], p[2], p[1]);
            push(p[0], p[3], p[2]);
          }
        }
    }
  const auto count = static_cast<std::uint32_t>(tris.size() / 12);
  std::string bytes(80, ' ');
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (std::uint32_t t = 0; t < count; ++t) {
    bytes.append(reinterpret_cast<const char*>(tris.data() + 12 * t), 48);
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST(SoupMerge, HundredThousandTrianglesReadFast) {
  const int n = 91;
  const std::string path = test::write_temp("gridded_box.stl", gridded_box_stl(n));
  const auto start = std::chrono::steady_clock::now();
  ReadReport report;
  const Plc3 p = read_plc(path, {}, &report);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(report.input_polygons, 12 * n * n);
  EXPECT_EQ(report.facets, 6);
  EXPECT_EQ(report.merged_exact, 12 * n * n - 6);
  // Each face keeps its 4n boundary grid points; interior grid points drop:
  // 8 corners + 12 edges of n - 1 points.
  EXPECT_EQ(p.vertices.size(), std::size_t(8 + 12 * (n - 1)));
  for (const Facet3& f : p.facets) {
    ASSERT_EQ(f.loops.size(), 1u);
    EXPECT_EQ(f.loops[0].size(), std::size_t(4 * n));
  }
  RecordProperty("seconds", std::to_string(seconds));
}

}  // namespace
}  // namespace pqmesh::detail
