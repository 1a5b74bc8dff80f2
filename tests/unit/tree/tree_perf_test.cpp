// Timing smoke tests (print, assert generously): ~1e6 leaves in 3D, neighbour queries
// over all of them, and balancing a deep point refinement.
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
  EXPECT_LT(build, 10.0);
  EXPECT_LT(bal, 10.0);
  EXPECT_LT(query, 20.0);
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
  EXPECT_LT(bal, 5.0);
}

}  // namespace
}  // namespace pqmesh
