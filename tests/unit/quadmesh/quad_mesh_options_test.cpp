// Size control, markers, determinism and option errors of the 2D quadtree mesher.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "pqmesh/check.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/mesh_io.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/read_domain.hpp"
#include "predicates/predicates.hpp"
#include "support/paths.hpp"
#include "support/random_domains.hpp"

namespace pqmesh {
namespace {

Domain2 corpus(const std::string& name) { return make_domain(read_pslg(test::data_path("2d/" + name))); }

double longest_edge(const TriMesh2& m, const std::array<int, 3>& t) {
  double best = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec2 a = m.vertices[static_cast<std::size_t>(t[k])], b = m.vertices[static_cast<std::size_t>(t[(k + 1) % 3])];
    best = std::max(best, std::hypot(b.x - a.x, b.y - a.y));
  }
  return best;
}

QuadMeshResult checked(const Domain2& d, const QuadMeshOptions& o = {}) {
  QuadMeshResult r = quad_mesh(d, o);
  const CheckReport check = check_mesh(r.mesh, d);
  EXPECT_TRUE(check.valid()) << check.to_text();
  return r;
}

// Boxes are at most max_size wide, so no triangle edge is longer than the box
// diagonal plus the warping of its ends (at most a quarter box each).
TEST(QuadMeshOptions, MaxSizeBoundsEveryTriangle) {
  const Domain2 d = corpus("l_shape.poly");
  const std::size_t coarse = checked(d).mesh.triangles.size();
  for (const double h : {0.1, 0.05, 0.02}) {
    QuadMeshOptions o;
    o.max_size = h;
    const QuadMeshResult r = checked(d, o);
    double longest = 0;
    for (const auto& t : r.mesh.triangles) longest = std::max(longest, longest_edge(r.mesh, t));
    EXPECT_LE(longest, (std::sqrt(2.0) + 0.5) * h) << "max size " << h;
    EXPECT_GT(r.mesh.triangles.size(), coarse);
  }
}

// A size field point asks for size s at p: triangles near p are small, far
// ones are not (the mesh is graded, not uniformly fine).
TEST(QuadMeshOptions, SizeFieldRefinesAroundAPoint) {
  const Domain2 d = corpus("square.poly");
  QuadMeshOptions o;
  o.size_field.points = {{0.3, 0.6}};
  o.size_field.sizes = {1e-3};
  const QuadMeshResult r = checked(d, o);
  double near_longest = 0, far_longest = 0;
  for (const auto& t : r.mesh.triangles) {
    const Vec2 a = r.mesh.vertices[static_cast<std::size_t>(t[0])];
    const double dist = std::hypot(a.x - 0.3, a.y - 0.6);
    if (dist < 0.004) near_longest = std::max(near_longest, longest_edge(r.mesh, t));
    if (dist > 0.3) far_longest = std::max(far_longest, longest_edge(r.mesh, t));
  }
  // f(x) = 1e-3 + |x - p| <= 5e-3 within 0.004 of p: boxes there are at most that.
  EXPECT_LE(near_longest, (std::sqrt(2.0) + 0.5) * 5e-3);
  EXPECT_GT(far_longest, 0.05);
  EXPECT_LT(r.mesh.triangles.size(), 20000u) << "refinement must be graded, not uniform";
}

TEST(QuadMeshOptions, BadSizeFieldIsInvalidInput) {
  const Domain2 d = corpus("square.poly");
  QuadMeshOptions o;
  o.size_field.points = {{0.5, 0.5}, {0.2, 0.2}};
  o.size_field.sizes = {0.1, -1};
  o.size_field.lines = {3, 4};
  o.size_field.path = "field.txt";
  try {
    quad_mesh(d, o);
    FAIL() << "a negative size was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.ids(), std::vector<std::int64_t>{1});
  }
  QuadMeshOptions m;
  m.max_size = -2;
  EXPECT_THROW(quad_mesh(d, m), InvalidInput);
}

// Every listed boundary edge carries the marker of the input segment it lies
// on (found independently by the exact rounding rule of the checker).
TEST(QuadMeshOptions, SegmentMarkersReachBoundaryEdges) {
  const Domain2 d = corpus("square_holes.poly");
  ASSERT_FALSE(d.pslg.segment_markers.empty());
  const QuadMeshResult r = checked(d);
  ASSERT_EQ(r.mesh.edges.size(), r.mesh.edge_markers.size());
  for (std::size_t e = 0; e < r.mesh.edges.size(); ++e) {
    const Vec2 p = r.mesh.vertices[static_cast<std::size_t>(r.mesh.edges[e][0])];
    const Vec2 q = r.mesh.vertices[static_cast<std::size_t>(r.mesh.edges[e][1])];
    int found = 0;
    for (std::size_t s = 0; s < d.pslg.segments.size(); ++s) {
      const Vec2 a = d.pslg.vertices[static_cast<std::size_t>(d.pslg.segments[s][0])];
      const Vec2 b = d.pslg.vertices[static_cast<std::size_t>(d.pslg.segments[s][1])];
      if (within_ulp_of_segment(p, a, b) && within_ulp_of_segment(q, a, b)) {
        ++found;
        EXPECT_EQ(r.mesh.edge_markers[e], d.pslg.segment_markers[s]) << "edge " << e;
      }
    }
    EXPECT_EQ(found, 1) << "edge " << e;
  }
}

TEST(QuadMeshOptions, RegionAttributeReachesTriangles) {
  const Domain2 d = corpus("regions.poly");
  const QuadMeshResult r = checked(d);
  ASSERT_EQ(r.mesh.triangle_markers.size(), r.mesh.triangles.size());
  EXPECT_EQ(static_cast<double>(r.mesh.triangle_markers.front()), d.pslg.regions.front().attribute);
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The size phase under a global cap alone skips the balance step (it would
// split nothing: quadtree_builder.cpp, run_phase). A size field whose sizes
// never bind (each at least the cap, so min_over is the cap everywhere) asks
// for exactly the same boxes but takes the balancing path: the two meshes must
// be the same, vertex for vertex and triangle for triangle.
TEST(QuadMeshOptions, UniformCapNeedsNoBalancingInTheSizePhase) {
  for (const std::string name : {"square_holes.poly", "comb.poly", "l_shape.poly"}) {
    const Domain2 d = corpus(name);
    const double h = 0.02 * std::max(d.bbox_max.x - d.bbox_min.x, d.bbox_max.y - d.bbox_min.y);
    QuadMeshOptions cap;
    cap.max_size = h;
    QuadMeshOptions field = cap;
    field.size_field.points = {d.bbox_min, d.bbox_max};
    field.size_field.sizes = {2 * h, 3 * h};
    const QuadMeshResult a = checked(d, cap), b = checked(d, field);
    EXPECT_GT(a.stats.splits_size, 0) << name;
    EXPECT_EQ(a.stats.splits_size, b.stats.splits_size) << name;
    EXPECT_EQ(a.stats.splits_balance, b.stats.splits_balance) << name;
    EXPECT_EQ(a.stats.leaves, b.stats.leaves) << name;
    EXPECT_EQ(a.mesh.vertices, b.mesh.vertices) << name;
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles) << name;
  }
}

// CGAL's determinism test: mesh twice, write, compare bytes.
TEST(QuadMeshOptions, OutputIsByteIdentical) {
  const auto dir = std::filesystem::temp_directory_path() / "pqmesh_quad_determinism";
  std::filesystem::create_directories(dir);
  for (const std::uint64_t seed : {3u, 17u, 99u}) {
    const Domain2 d = make_domain(test::random_polygon_with_holes(seed));
    for (const char* ext : {".vtu", ".msh", ".node"}) {
      const std::string a = (dir / ("a" + std::to_string(seed) + ext)).string();
      const std::string b = (dir / ("b" + std::to_string(seed) + ext)).string();
      write_mesh(quad_mesh(d).mesh, a);
      write_mesh(quad_mesh(d).mesh, b);
      const std::string ba = bytes_of(a);
      EXPECT_FALSE(ba.empty());
      EXPECT_EQ(ba, bytes_of(b)) << "seed " << seed << " " << ext;
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pqmesh
