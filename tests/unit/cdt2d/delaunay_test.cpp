// Unconstrained Delaunay triangulations from cdt2d: random, grid (massively
// cocircular), collinear and nearly collinear inputs, determinism, and a
// printed throughput figure (no timing assertion).
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cdt_test_util.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::cdt2d::test {
namespace {

TEST(CdtDelaunay, RandomPointsInInputAndZOrder) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    CdtInput in;
    in.points = random_points(seed, 50 + static_cast<int>(seed) * 97);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "random seed " + std::to_string(seed));
    sort_z_order(in.points);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "z-order seed " + std::to_string(seed));
  }
}

// Large incoherent (random) input orders are re-ordered internally; the
// result must still be a Delaunay triangulation of all points.
TEST(CdtDelaunay, LargeRandomOrder) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    CdtInput in;
    in.points = random_points(seed + 500, 6000);
    for (int i = 0; i < 50; ++i) in.points.push_back({0.25 + i / 256.0, 0.75});  // a collinear run at the end
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "random order seed " + std::to_string(seed));
  }
}

TEST(CdtDelaunay, SmallInputs) {
  CdtInput in;
  in.points = {{0, 0}, {1, 0}, {0, 1}};
  const Tris t = constrained_delaunay(in, false).triangles;
  ASSERT_EQ(t.size(), 1u);
  expect_cdt(in.points, {}, t, "one triangle");
  in.points = {{0, 0}, {1, 0}};
  EXPECT_TRUE(constrained_delaunay(in, false).triangles.empty());
  in.points = {};
  EXPECT_TRUE(constrained_delaunay(in, false).triangles.empty());
}

// Grid points: every unit square has four cocircular corners, so nearly
// every incircle test is an exact tie; ties never flip.
TEST(CdtDelaunay, GridPointsInSeveralOrders) {
  for (int m : {2, 3, 7, 24}) {
    std::vector<Vec2> grid;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m + 1; ++j) grid.push_back({0.5 * i, 0.5 * j});
    CdtInput in;
    in.points = grid;
    const Tris rowmajor = constrained_delaunay(in, false).triangles;
    expect_cdt(in.points, {}, rowmajor, "grid row-major m=" + std::to_string(m));
    EXPECT_EQ(static_cast<int>(rowmajor.size()), 2 * (m - 1) * m);  // two per cell
    std::mt19937_64 rng(static_cast<std::uint64_t>(m));
    std::shuffle(in.points.begin(), in.points.end(), rng);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "grid shuffled m=" + std::to_string(m));
    sort_z_order(in.points);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "grid z-order m=" + std::to_string(m));
  }
}

// A rectilinear grid with unequal dyadic spacings: every cell is a rectangle
// of its own shape, whose corners are exactly cocircular (the tie legalize()
// recognises from coordinates alone, without incircle).
TEST(CdtDelaunay, RectilinearGridWithUnequalSpacing) {
  std::mt19937_64 rng(11);
  for (int m : {3, 9, 30}) {
    std::vector<double> xs{0}, ys{0};
    for (int i = 1; i < m; ++i) xs.push_back(xs.back() + static_cast<double>(1 + rng() % 7) / 8);
    for (int j = 1; j <= m; ++j) ys.push_back(ys.back() + static_cast<double>(1 + rng() % 5) / 16);
    CdtInput in;
    for (const double x : xs)
      for (const double y : ys) in.points.push_back({x, y});
    const std::string name = "rectilinear m=" + std::to_string(m);
    const Tris rowmajor = constrained_delaunay(in, false).triangles;
    expect_cdt(in.points, {}, rowmajor, name + " row-major");
    EXPECT_EQ(static_cast<int>(rowmajor.size()), 2 * (m - 1) * m);  // two per cell
    std::shuffle(in.points.begin(), in.points.end(), rng);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, name + " shuffled");
    sort_z_order(in.points);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, name + " z-order");
  }
}

// Points on concentric circles (exactly cocircular: Pythagorean triples).
TEST(CdtDelaunay, CocircularPythagoreanPoints) {
  std::vector<Vec2> pts;
  for (int s : {1, 2, 3}) {
    const double r = 5.0 * s;
    for (auto [a, b] : {std::pair{3, 4}, std::pair{4, 3}, std::pair{5, 0}, std::pair{0, 5}})
      for (int sx : {-1, 1})
        for (int sy : {-1, 1}) {
          const Vec2 p{sx * a * r / 5.0, sy * b * r / 5.0};
          if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
        }
  }
  pts.push_back({0, 0});
  CdtInput in;
  in.points = pts;
  expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "pythagorean circles");
}

TEST(CdtDelaunay, AllCollinearGivesNoTriangles) {
  CdtInput in;
  for (int i = 0; i < 10; ++i) in.points.push_back({1.0 * i, 2.0 * i});
  EXPECT_TRUE(constrained_delaunay(in, false).triangles.empty());
  in.points.push_back({3.0, 6.0});  // duplicate of point 3
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
}

// Long collinear runs first (the first triangle needs a point off the line),
// on the hull and through the interior.
TEST(CdtDelaunay, CollinearRuns) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    std::mt19937_64 rng(seed);
    CdtInput in;
    for (int i = 0; i < 40; ++i) in.points.push_back({i / 8.0, 0.0});           // bottom hull side
    for (int i = 1; i < 30; ++i) in.points.push_back({i / 8.0, i / 16.0});      // diagonal
    for (int i = 0; i < 30; ++i) in.points.push_back({0.125 + i / 16.0, 1.0});  // top side
    for (int i = 0; i < 60; ++i) in.points.push_back({unit(rng) * 4.875, unit(rng)});
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "collinear runs");
    std::shuffle(in.points.begin() + 1, in.points.end(), rng);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "collinear runs shuffled");
  }
}

// Chains whose consecutive points are within an ulp of a straight line.
std::vector<Vec2> nearly_straight_chains(std::uint64_t seed, int chains, int per_chain) {
  std::mt19937_64 rng(seed);
  std::vector<Vec2> pts;
  for (int c = 0; c < chains; ++c) {
    const double slope = 0.1 + 0.3 * unit(rng), offset = 0.25 + c * 1e-9;
    for (int i = 0; i < per_chain; ++i) {
      const double x = i / 1024.0;
      double y = slope * x + offset;
      const std::uint64_t r = rng() % 3;
      if (r == 0) y = std::nextafter(y, 2.0);
      if (r == 1) y = std::nextafter(y, -2.0);
      pts.push_back({x, y});
    }
  }
  return pts;
}

TEST(CdtDelaunay, NearlyStraightChains) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    CdtInput in;
    in.points = nearly_straight_chains(seed, 3, 300);
    expect_cdt(in.points, {}, constrained_delaunay(in, false).triangles, "chains seed " + std::to_string(seed));
  }
}

TEST(CdtDelaunay, DuplicatePointThrows) {
  CdtInput in;
  in.points = random_points(7, 200);
  in.points.push_back(in.points[123]);
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
  in.points = {{0, 0}, {0, 0}, {1, 1}};
  EXPECT_THROW(constrained_delaunay(in, false), InternalError);
}

TEST(CdtDelaunay, DeterministicOutput) {
  CdtInput in;
  in.points = random_points(99, 5000);
  in.points.push_back({0.5, 0.5});
  for (int i = 0; i < 30; ++i) in.points.push_back({0.25 + i / 128.0, 0.125});
  const Tris a = constrained_delaunay(in, false).triangles;
  const Tris b = constrained_delaunay(in, false).triangles;
  EXPECT_EQ(a, b);
}

// Throughput for z-ordered random points; printed, never asserted (timing
// belongs to bench/). The mesh is still fully checked.
TEST(CdtDelaunay, ThroughputOfZOrderedPoints) {
  const int n = 1000000;
  CdtInput in;
  in.points = random_points(2024, n);
  sort_z_order(in.points);
  const auto t0 = std::chrono::steady_clock::now();
  const Tris t = constrained_delaunay(in, false).triangles;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ cdt2d    ] %d z-ordered points in %.3f s: %.0f points/s\n", n, s, n / s);
  const int h = hull_boundary_count(in.points);
  EXPECT_EQ(static_cast<long>(t.size()), 2L * n - h - 2);
  const CheckReport report = check_mesh_topology(to_mesh(in.points, t, false));
  EXPECT_TRUE(report.valid()) << report.to_text();
}

}  // namespace
}  // namespace pqmesh::cdt2d::test
