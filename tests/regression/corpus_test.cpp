// Every good file of data/2d and data/3d reads, validates, and has the counts, shells and
// volume/area derived by hand when the file was designed (data/generate_corpus.py builds the
// same numbers exactly with rationals and asserts them; the derivations are repeated below).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/read_domain.hpp"
#include "support/paths.hpp"

namespace pqmesh {
namespace {

// ---------------------------------------------------------------------------------------------
// 3D

struct Good3 {
  const char* file;
  int vertices;
  int facets;      // after merging coplanar soup triangles
  int edges;       // V + F_loops-based count: each closed shell of genus g has E = V + F - 2 + 2g (disk facets)
  int shells;
  int triangles;   // facet triangulation without new vertices: sum over facets of (#loop vertices + 2 #holes - 2)
  double volume;
  int soup_polygons;  // ReadReport::input_polygons for soups, -1 for TetGen files
  int welded;         // ReadReport::welded_vertices for STL, -1 otherwise
};

void PrintTo(const Good3& g, std::ostream* out) { *out << g.file; }

// Derivations (V, F, E, triangles T = 2V - 4 + 4g per shell of genus g, volume):
//  cube:         8, 6, 12, T 12, volume 1.
//  l_block:      L of area 3 (2x2 minus 1x1) extruded by 1: 12 vertices, 2 caps + 6 walls, 18 edges,
//                T = 2*12 - 4 = 20, volume 3.
//  cube_cavity:  two cubes (16, 12, 24, T 12 + 12), volume 4^3 - 2^3 = 56, 2 shells.
//  prongs_slot:  8-gon cross-section (area 1 - (1/1024)(3/4) = 4093/4096) extruded by 1/4:
//                16, 10, 24, T 28, volume 4093/16384.
//  wedge_Xdeg:   triangle (0,0) (1,0) (1,t) extruded by 1: 6, 5, 9, T 8, volume t/2 with
//                t = 717/8192 (5 deg) and 143/8192 (1 deg).
//  star_vertex:  12-gon (c = 887/1024 rounds cos 30 deg) + apex: 13, 13, 24, T 22;
//                area 3/2 + 2c^2, volume area/3 = 1573201/1572864.
//  plate_holes:  4x4x1/2 plate with four 1x1 holes: 8 + 4*8 = 40 vertices, 2 caps + 4 + 16 walls = 22,
//                12 + 4*12 = 60 edges, genus 4: T = 80 - 4 + 16 = 92, volume 12/2 = 6.
//  channel_patches: 4x1x1 box (8 vertices) with a 1 x 1/2 patch (4) in its bottom: 12 vertices,
//                7 facets (the bottom with the patch as a hole loop, the patch, 5 walls), 12 + 4
//                edges (the patch's are flat); T = bottom 8 + 2 - 2 = 8, patch 2, walls 5 * 2 = 10:
//                20; volume 4.
//  cube_through_hole: 16 vertices, 16 quads; the domain merges the coplanar same-marker quads of
//                each cap into one facet with a hole loop (TetGen's default), leaving 24 edges;
//                genus 1: T = 32, volume 64 - 16 = 48.
//  schoenhardt:  6, 8, 12, T 8; volume 887/1024 (exact, from the generator's rational computation;
//                the other diagonal choice, the convex hull, has 3389777/2097152).
//  fins:         32-gon cross-section of area 15/64 + 8(1/16)(3/4) = 39/64, depth 1: 64, 34, 96,
//                T = 124, volume 39/64.
//  cube.off:     unit cube, 4 quads + 4 triangles in the file: 8, 6, 12, T 12, volume 1.
//  cube.obj:     [0,2]^3 with 2 extra vertices on top edges: 10, 6, 12 + 2 = 14 edges, T = 16,
//                13 polygons in the file (4 + 3 + 3 triangles, 3 quads), volume 8.
//  STL cubes:    12 triangles, 36 corners welded to 8 (28 welded), 6 facets, volume 1.
//  box_with_hole: 4x4x1 with a 2x2 hole: 32 triangles, 96 corners welded to 16 (80), 10 facets
//                (caps with a hole loop), 24 edges, genus 1: T = 32, volume 16 - 4 = 12.
//  l_block.mesh: the L-block as 20 triangles: 12, 8, 18, T 20, volume 3.
const Good3 kGood3[] = {
    {"3d/cube.poly", 8, 6, 12, 1, 12, 1.0, -1, -1},
    {"3d/l_block.poly", 12, 8, 18, 1, 20, 3.0, -1, -1},
    {"3d/cube_cavity.poly", 16, 12, 24, 2, 24, 56.0, -1, -1},
    {"3d/prongs_slot.poly", 16, 10, 24, 1, 28, 4093.0 / 16384.0, -1, -1},
    {"3d/wedge_5deg.poly", 6, 5, 9, 1, 8, 717.0 / 16384.0, -1, -1},
    {"3d/wedge_1deg.poly", 6, 5, 9, 1, 8, 143.0 / 16384.0, -1, -1},
    {"3d/tuning_fork.poly", 24, 14, 36, 1, 44, 5939.0 / 32768.0, -1, -1},
    {"3d/heat_sink.poly", 72, 38, 108, 1, 140, 409.0 / 16384.0, -1, -1},
    {"3d/star_vertex.poly", 13, 13, 24, 1, 22, 1573201.0 / 1572864.0, -1, -1},
    {"3d/plate_holes.poly", 40, 22, 60, 1, 92, 6.0, -1, -1},
    {"3d/channel_patches.poly", 12, 7, 16, 1, 20, 4.0, -1, -1},
    {"3d/cube_through_hole.poly", 16, 16, 24, 1, 32, 48.0, -1, -1},
    {"3d/schoenhardt.poly", 6, 8, 12, 1, 8, 887.0 / 1024.0, -1, -1},
    {"3d/fins.poly", 64, 34, 96, 1, 124, 39.0 / 64.0, -1, -1},
    {"3d/cube.off", 8, 6, 12, 1, 12, 1.0, 8, -1},
    {"3d/cube.obj", 10, 6, 14, 1, 16, 8.0, 13, -1},
    {"3d/cube_ascii.stl", 8, 6, 12, 1, 12, 1.0, 12, 28},
    {"3d/cube_binary.stl", 8, 6, 12, 1, 12, 1.0, 12, 28},
    {"3d/box_with_hole.stl", 16, 10, 24, 1, 32, 12.0, 32, 80},
    {"3d/l_block.mesh", 12, 8, 18, 1, 20, 3.0, 20, -1},
    {"3d/cube.smesh", 8, 6, 12, 1, 12, 1.0, -1, -1},
};

double det3(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

class Corpus3 : public ::testing::TestWithParam<Good3> {};

TEST_P(Corpus3, ReadsValidatesAndMatchesCounts) {
  const Good3& g = GetParam();
  const std::string path = test::data_path(g.file);
  ASSERT_EQ(domain_dimension(path), 3);
  Plc3 plc;
  ReadReport report;
  try {
    plc = read_plc(path, ReadOptions{}, &report);
  } catch (const std::exception& e) {
    FAIL() << "read_plc threw: " << e.what();
  }
  EXPECT_EQ(static_cast<int>(plc.vertices.size()), g.vertices);
  EXPECT_EQ(static_cast<int>(plc.facets.size()), g.facets);
  if (g.soup_polygons >= 0) {
    EXPECT_EQ(report.input_polygons, g.soup_polygons);
    EXPECT_EQ(report.facets, g.facets);
    EXPECT_EQ(report.merged_near, 0);  // default options merge exactly coplanar polygons only
  }
  if (g.welded >= 0) {
    EXPECT_EQ(report.welded_vertices, g.welded);
  }

  Domain3 d;
  try {
    d = make_domain(plc);
  } catch (const std::exception& e) {
    FAIL() << "make_domain threw: " << e.what();
  }
  EXPECT_EQ(static_cast<int>(d.edges.size()), g.edges);
  ASSERT_EQ(static_cast<int>(d.shells.size()), g.shells);
  EXPECT_TRUE(d.shells[0].exterior);
  for (std::size_t s = 1; s < d.shells.size(); ++s) {
    EXPECT_FALSE(d.shells[s].exterior);
  }
  std::size_t shell_facets = 0;
  for (const auto& s : d.shells) shell_facets += s.facets.size();
  EXPECT_EQ(shell_facets, d.plc.facets.size());
  EXPECT_EQ(static_cast<int>(d.facet_triangles.size()), g.triangles);
  EXPECT_EQ(d.facet_triangle_owner.size(), d.facet_triangles.size());
  EXPECT_TRUE(std::is_sorted(d.facet_triangle_owner.begin(), d.facet_triangle_owner.end()));
  EXPECT_EQ(d.facet_normals.size(), d.plc.facets.size());
  EXPECT_NEAR(d.volume, g.volume, 1e-12 * std::max(1.0, g.volume));

  // Every edge on exactly two facets, sorted by (a, b).
  for (std::size_t i = 0; i < d.edges.size(); ++i) {
    const auto& e = d.edges[i];
    EXPECT_LT(e.a, e.b);
    EXPECT_GE(e.facets[0], 0);
    EXPECT_GE(e.facets[1], 0);
    EXPECT_NE(e.facets[0], e.facets[1]);
    if (i > 0) {
      EXPECT_LT(std::make_pair(d.edges[i - 1].a, d.edges[i - 1].b), std::make_pair(e.a, e.b));
    }
  }
  // The facet triangles are oriented outward: their signed volumes add up to the volume.
  double tri_volume = 0;
  for (const auto& t : d.facet_triangles) {
    tri_volume += det3(d.plc.vertices[t[0]], d.plc.vertices[t[1]], d.plc.vertices[t[2]]) / 6;
  }
  EXPECT_NEAR(tri_volume, g.volume, 1e-12 * std::max(1.0, g.volume));
}

std::string file_case_name(const std::string& file) {
  std::string name = file;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

std::string name3(const ::testing::TestParamInfo<Good3>& p) { return file_case_name(p.param.file); }

INSTANTIATE_TEST_SUITE_P(Files, Corpus3, ::testing::ValuesIn(kGood3), name3);

// cube.poly: facets in file order are bottom, top, y=0, x=1, y=1, x=0 with markers 1..6; after
// orientation their unit normals point out of the cube; the bounding box is exactly [0,1]^3.
TEST(CorpusDetails, CubeMarkersNormalsAndBox) {
  const Domain3 d = make_domain(read_plc(test::data_path("3d/cube.poly")));
  ASSERT_EQ(d.plc.facets.size(), 6u);
  const Vec3 expected[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(d.plc.facets[f].marker, f + 1);
    EXPECT_NEAR(d.facet_normals[f].x, expected[f].x, 1e-15) << "facet " << f;
    EXPECT_NEAR(d.facet_normals[f].y, expected[f].y, 1e-15) << "facet " << f;
    EXPECT_NEAR(d.facet_normals[f].z, expected[f].z, 1e-15) << "facet " << f;
  }
  EXPECT_EQ(d.bbox_min.x, 0.0);
  EXPECT_EQ(d.bbox_min.y, 0.0);
  EXPECT_EQ(d.bbox_min.z, 0.0);
  EXPECT_EQ(d.bbox_max.x, 1.0);
  EXPECT_EQ(d.bbox_max.y, 1.0);
  EXPECT_EQ(d.bbox_max.z, 1.0);
}

// cube_cavity.poly: facets 6..11 (the cavity [1,3]^3) form the floater; oriented outward from P
// they point into the cavity, towards its centre (2,2,2). The TetGen hole point is read.
TEST(CorpusDetails, CavityShellPointsIntoTheCavity) {
  const Domain3 d = make_domain(read_plc(test::data_path("3d/cube_cavity.poly")));
  ASSERT_EQ(d.shells.size(), 2u);
  std::vector<int> floater = d.shells[1].facets;
  std::sort(floater.begin(), floater.end());
  EXPECT_EQ(floater, (std::vector<int>{6, 7, 8, 9, 10, 11}));
  ASSERT_EQ(d.plc.holes.size(), 1u);
  const Vec3 centre{2, 2, 2};
  for (int f = 6; f < 12; ++f) {
    const Vec3 p = d.plc.vertices[d.plc.facets[f].loops[0][0]];
    EXPECT_GT(dot(d.facet_normals[f], centre - p), 0.0) << "cavity facet " << f << " points away from the cavity";
  }
  for (int f = 0; f < 6; ++f) {
    const Vec3 p = d.plc.vertices[d.plc.facets[f].loops[0][0]];
    EXPECT_LT(dot(d.facet_normals[f], centre - p), 0.0) << "outer facet " << f << " points inwards";
  }
}

// plate_holes.poly: the top and bottom facets (file order: bottom, top) have 4 hole loops each.
TEST(CorpusDetails, PlateFacetsKeepTheirHoleLoops) {
  const Domain3 d = make_domain(read_plc(test::data_path("3d/plate_holes.poly")));
  ASSERT_GE(d.plc.facets.size(), 2u);
  EXPECT_EQ(d.plc.facets[0].loops.size(), 5u);
  EXPECT_EQ(d.plc.facets[1].loops.size(), 5u);
  EXPECT_EQ(d.plc.facets[0].loops[0].size(), 4u);  // outer loop first
}

// box_with_hole.stl: the merged top and bottom facets each have one hole loop.
TEST(CorpusDetails, MergedSoupFacetsWithHoles) {
  const Plc3 plc = read_plc(test::data_path("3d/box_with_hole.stl"));
  int with_hole = 0;
  for (const auto& f : plc.facets) {
    if (f.loops.size() == 2) ++with_hole;
    EXPECT_LE(f.loops.size(), 2u);
  }
  EXPECT_EQ(with_hole, 2);
}

// ---------------------------------------------------------------------------------------------
// 2D

struct Good2 {
  const char* file;
  int vertices;
  int segments;
  int loops;   // 1 + number of holes
  double area;
};

void PrintTo(const Good2& g, std::ostream* out) { *out << g.file; }

// Derivations: square 1; L 2*2 - 1 = 3; square_holes 16 - 1 - 1 - (2*1)/2 = 13 (4+4+4+3 vertices);
// comb: spine 245/256 wide, 6 teeth of 5/32 and 5 slots of 1/256 (6*5/32 + 5/256 = 245/256),
// area 245/256 - 5 (1/256)(3/4) = 965/1024, 24 vertices; spikes: unit square plus a triangle of
// base 2h and height 1, area 1 + h, h = 5734, 2861, 572 / 65536 (tan of half the tip angle);
// regions: 2x2 minus 1x1 = 3.
const Good2 kGood2[] = {
    {"2d/square.poly", 4, 4, 1, 1.0},
    {"2d/l_shape.poly", 6, 6, 1, 3.0},
    {"2d/square_holes.poly", 15, 15, 4, 13.0},
    {"2d/comb.poly", 24, 24, 1, 965.0 / 1024.0},
    {"2d/spike_10deg.poly", 7, 7, 1, 1.0 + 5734.0 / 65536.0},
    {"2d/spike_5deg.poly", 7, 7, 1, 1.0 + 2861.0 / 65536.0},
    {"2d/spike_1deg.poly", 7, 7, 1, 1.0 + 572.0 / 65536.0},
    {"2d/regions.poly", 8, 8, 2, 3.0},
};

double loop_signed_area(const Pslg2& p, const std::vector<int>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 u = p.vertices[loop[i]];
    const Vec2 v = p.vertices[loop[(i + 1) % loop.size()]];
    a += u.x * v.y - v.x * u.y;
  }
  return a / 2;
}

class Corpus2 : public ::testing::TestWithParam<Good2> {};

TEST_P(Corpus2, ReadsValidatesAndMatchesCounts) {
  const Good2& g = GetParam();
  const std::string path = test::data_path(g.file);
  ASSERT_EQ(domain_dimension(path), 2);
  Pslg2 pslg;
  try {
    pslg = read_pslg(path);
  } catch (const std::exception& e) {
    FAIL() << "read_pslg threw: " << e.what();
  }
  EXPECT_EQ(static_cast<int>(pslg.vertices.size()), g.vertices);
  EXPECT_EQ(static_cast<int>(pslg.segments.size()), g.segments);
  Domain2 d;
  try {
    d = make_domain(pslg);
  } catch (const std::exception& e) {
    FAIL() << "make_domain threw: " << e.what();
  }
  ASSERT_EQ(static_cast<int>(d.loops.size()), g.loops);
  ASSERT_EQ(d.loop_segments.size(), d.loops.size());
  EXPECT_NEAR(d.area, g.area, 1e-12 * std::max(1.0, g.area));
  // Outer loop counter-clockwise, holes clockwise, every segment in exactly one loop, and the
  // signed loop areas add up to the area.
  double sum = 0;
  std::size_t total = 0;
  std::set<int> segs;
  for (std::size_t i = 0; i < d.loops.size(); ++i) {
    const double a = loop_signed_area(d.pslg, d.loops[i]);
    if (i == 0) {
      EXPECT_GT(a, 0) << "outer loop not counter-clockwise";
    } else {
      EXPECT_LT(a, 0) << "hole loop " << i << " not clockwise";
    }
    sum += a;
    ASSERT_EQ(d.loop_segments[i].size(), d.loops[i].size());
    total += d.loops[i].size();
    for (std::size_t k = 0; k < d.loops[i].size(); ++k) {
      const int s = d.loop_segments[i][k];
      ASSERT_GE(s, 0);
      ASSERT_LT(s, static_cast<int>(d.pslg.segments.size()));
      segs.insert(s);
      const int a0 = d.loops[i][k], a1 = d.loops[i][(k + 1) % d.loops[i].size()];
      const auto& seg = d.pslg.segments[s];
      EXPECT_TRUE((seg[0] == a0 && seg[1] == a1) || (seg[0] == a1 && seg[1] == a0))
          << "loop " << i << " position " << k << " is not segment " << s;
    }
  }
  EXPECT_EQ(total, d.pslg.segments.size());
  EXPECT_EQ(segs.size(), d.pslg.segments.size());
  EXPECT_NEAR(sum, g.area, 1e-12 * std::max(1.0, g.area));
}

std::string name2(const ::testing::TestParamInfo<Good2>& p) { return file_case_name(p.param.file); }

INSTANTIATE_TEST_SUITE_P(Files, Corpus2, ::testing::ValuesIn(kGood2), name2);

// square.poly: segment markers 1..4; square_holes.poly: 3 hole points; regions.poly: two
// regions (1/4,1/4) attribute 7 max area 1/8 and (7/4,7/4) attribute -3 with no area constraint.
TEST(CorpusDetails, MarkersHolesAndRegions2) {
  const Pslg2 sq = read_pslg(test::data_path("2d/square.poly"));
  EXPECT_EQ(sq.segment_markers, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(read_pslg(test::data_path("2d/square_holes.poly")).holes.size(), 3u);
  const Pslg2 r = read_pslg(test::data_path("2d/regions.poly"));
  ASSERT_EQ(r.regions.size(), 2u);
  EXPECT_EQ(r.regions[0].point.x, 0.25);
  EXPECT_EQ(r.regions[0].point.y, 0.25);
  EXPECT_EQ(r.regions[0].attribute, 7.0);
  EXPECT_EQ(r.regions[0].max_area, 0.125);
  EXPECT_EQ(r.regions[1].attribute, -3.0);
  EXPECT_LT(r.regions[1].max_area, 0.0);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_EQ(r.holes[0].x, 1.0);
  EXPECT_EQ(r.holes[0].y, 1.0);
}

// Every file in data/2d and data/3d has an entry above (and every entry exists), so a new corpus
// file cannot slip in untested.
TEST(CorpusDetails, EveryCorpusFileIsChecked) {
  std::set<std::string> listed;
  for (const auto& g : kGood3) listed.insert(g.file);
  for (const auto& g : kGood2) listed.insert(g.file);
  std::set<std::string> present;
  for (const char* dir : {"2d", "3d"}) {
    for (const auto& e : std::filesystem::directory_iterator(test::data_path(dir))) {
      present.insert(std::string(dir) + "/" + e.path().filename().string());
    }
  }
  EXPECT_EQ(present, listed);
}

}  // namespace
}  // namespace pqmesh
