// The grid evaluator scales: many queries on a polygon with thousands of
// edges cost about O(log n) each, far from the O(n^2) of the brute force
// (times are printed for information, not asserted: performance belongs to benchmarks).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/lfs.hpp"

namespace pqmesh {
namespace {

// A wavy disk (n vertices, radius 1 +- 0.1) with a round hole (n / 4
// vertices, radius 0.4): loops are simple and disjoint by construction.
Domain2 wavy_annulus(int n) {
  Pslg2 g;
  const double two_pi = 6.283185307179586;
  for (int k = 0; k < n; ++k) {
    const double t = two_pi * k / n, r = 1 + 0.1 * std::sin(37 * t);
    g.vertices.push_back({r * std::cos(t), r * std::sin(t)});
    g.segments.push_back({k, (k + 1) % n});
  }
  const int m = n / 4;
  for (int k = 0; k < m; ++k) {
    const double t = two_pi * k / m;
    g.vertices.push_back({0.4 * std::cos(t), 0.4 * std::sin(t)});
    g.segments.push_back({n + k, n + (k + 1) % m});
  }
  g.holes.push_back({0, 0});
  return make_domain(g);
}

TEST(LfsPerf, ManyQueriesOnALargePolygon) {
  const Domain2 d = wavy_annulus(1600);
  const auto t0 = std::chrono::steady_clock::now();
  const LocalFeatureSize2 lfs(d);
  std::mt19937_64 rng(11);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<Vec2> xs;
  for (int k = 0; k < 200000; ++k) xs.push_back({2.4 * u() - 1.2, 2.4 * u() - 1.2});
  double sum = 0;
  for (Vec2 x : xs) sum += lfs.at(x);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("2000 edges, grid %d x %d: 200000 queries in %.3f s (%.2f us each)\n", lfs.grid_columns(),
              lfs.grid_rows(), seconds, 1e6 * seconds / 200000);
  EXPECT_GT(sum, 0);
  // Spot check against the brute force (2000 edges + 2000 vertices: 8e6 pairs per point).
  for (int k = 0; k < 40; ++k) EXPECT_EQ(lfs.at(xs[static_cast<std::size_t>(k)]), local_feature_size(d, xs[static_cast<std::size_t>(k)]));
}

TEST(LfsPerf, IntegralOnALargePolygon) {
  const Domain2 d = wavy_annulus(1600);
  const auto t0 = std::chrono::steady_clock::now();
  const LfsIntegral r = lfs_integral(d);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("2000 edges: I = %.1f, %lld cells, min lfs %.3g, %.3f s\n", r.value, static_cast<long long>(r.cells),
              r.min_lfs, seconds);
  EXPECT_GT(r.value, 0);
}

}  // namespace
}  // namespace pqmesh
