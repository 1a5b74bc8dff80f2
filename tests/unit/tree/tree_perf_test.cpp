// Scale tests (the figures are printed for information; performance is judged by benchmarks,
// not here): ~1e6 leaves in 3D, neighbour queries over all of them, and balancing a deep point refinement.
#include <chrono>
#include <cstdio>

#include "tree_test_util.hpp"

namespace pqmesh {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Uniform level 6 (262144 leaves), then every leaf with x cell < 26 split once more:
// 262144 + 26*64*64*7 = 1007616 leaves (by hand).
TEST(TreePerf, MillionLeavesOctree) {
  auto t0 = std::chrono::steady_clock::now();
  auto t = test::unit_tree<3>();
  test::refine_uniform(t, 6);
  for (std::int32_t n : test::live_leaves(t))
    if (t.key(n).q[0] / 2 < 26) t.split(n);
  const double build = seconds_since(t0);
  ASSERT_EQ(t.leaf_count(), 1007616);

  t0 = std::chrono::steady_clock::now();
  const std::int64_t splits = t.balance_all();
  const double bal = seconds_since(t0);
  EXPECT_EQ(splits, 0);  // already balanced: levels 6 and 7 only

  t0 = std::chrono::steady_clock::now();
  std::vector<std::int32_t> nb;
  std::int64_t total = 0;
  for (std::int32_t n = 0; n < t.size(); ++n)
    if (t.is_leaf(n)) {
      t.neighbours(n, nb);
      total += static_cast<std::int64_t>(nb.size());
    }
  const double query = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  const auto ls = t.leaves();
  const double order = seconds_since(t0);
  EXPECT_EQ(ls.size(), 1007616u);
  std::printf("[perf] octree 1007616 leaves: build %.3fs, balance check %.3fs, all neighbours %.3fs "
              "(%lld pairs), z-order %.3fs\n",
              build, bal, query, static_cast<long long>(total), order);
}

TEST(TreePerf, BalanceDeepPointRefinementOctree) {
  auto t = test::unit_tree<3>();
  const std::array<double, 3> p{0.3, 0.6, 0.45};
  auto t0 = std::chrono::steady_clock::now();
  for (int l = 0; l < 24; ++l) t.split(t.leaves_containing(p).at(0));
  const auto t1 = std::chrono::steady_clock::now();
  const std::int64_t splits = t.balance_all();
  const double bal = seconds_since(t1);
  std::printf("[perf] octree depth-24 point refinement: %lld balance splits, %d leaves, %.3fs (refine %.3fs)\n",
              static_cast<long long>(splits), t.leaf_count(), bal,
              std::chrono::duration<double>(t1 - t0).count());
}

// Many refinement sites: 400 pseudo-random points, each refined to depth 12, then one
// balance pass (linear in the number of splits).
TEST(TreePerf, BalanceManyPointsOctree) {
  auto t = test::unit_tree<3>();
  std::uint64_t s = 12345;
  auto next = [&] {  // LCG in (0, 1), never dyadic enough to land on a plane
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(s >> 11) + 0.5) * 0x1p-53;
  };
  std::vector<std::int32_t> at;
  for (int i = 0; i < 400; ++i) {
    const std::array<double, 3> p{next(), next(), next()};
    for (;;) {
      t.leaves_containing(p, at);
      ASSERT_EQ(at.size(), 1u);
      if (t.level(at[0]) >= 12) break;
      t.split(at[0]);
    }
  }
  const std::int32_t before = t.leaf_count();
  const auto t0 = std::chrono::steady_clock::now();
  const std::int64_t splits = t.balance_all();
  const double bal = seconds_since(t0);
  std::printf("[perf] octree 400 points to depth 12: %d -> %d leaves, %lld balance splits, %.3fs\n", before,
              t.leaf_count(), static_cast<long long>(splits), bal);
  EXPECT_GT(splits, 0);
}

}  // namespace
}  // namespace pqmesh
