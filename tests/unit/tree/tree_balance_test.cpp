// Balance (thesis §4.1.1 balance condition), protection, callbacks, determinism.
#include <random>
#include <stdexcept>

#include "tree_test_util.hpp"

namespace pqmesh {
namespace {

using test::Dims;

template <class T>
class TreeBalance : public ::testing::Test {};
TYPED_TEST_SUITE(TreeBalance, Dims);

// A point with non-dyadic coordinates: never on a box plane.
template <int D>
std::array<double, D> probe() {
  if constexpr (D == 2)
    return {0.3, 0.6};
  else
    return {0.3, 0.6, 0.45};
}

// Splits the leaf containing p until it is at `depth`.
template <int D>
void refine_at(Tree<D>& t, const std::array<double, D>& p, int depth) {
  for (;;) {
    const auto at = t.leaves_containing(p);
    if (at.size() != 1) throw std::logic_error("probe point on a plane");
    if (t.level(at[0]) >= depth) return;
    t.split(at[0]);
  }
}

// Largest level difference between neighbouring leaves, by brute force over pairs
// (optionally ignoring pairs that involve `skip`).
template <int D>
int worst_gap(const Tree<D>& t, std::int32_t skip = -1) {
  const auto ls = test::live_leaves(t);
  int worst = 0;
  for (std::size_t i = 0; i < ls.size(); ++i)
    for (std::size_t j = i + 1; j < ls.size(); ++j) {
      if (ls[i] == skip || ls[j] == skip) continue;
      if (test::brute_touch(t, ls[i], ls[j]) && !test::brute_overlap(t, ls[i], ls[j]))
        worst = std::max(worst, std::abs(t.level(ls[i]) - t.level(ls[j])));
    }
  return worst;
}

// Leaf bound after balancing a refinement around one point to depth d (derived by
// hand). Let U_l be the union of the level-l boxes that are split. A level-l leaf is
// split by balance only when it touches a split level-(l+1) box, so U_l lies within
// Chebyshev distance e_l of the point with e_l <= e_{l+1} + h(l), e_{d-1} <= h(d-1);
// hence e_l <= 2 h(l) and U_l meets at most 5 cells per axis: at most 5^D split
// boxes per level, each adding 2^D - 1 leaves: leaves <= d * 5^D * (2^D - 1) + 1.
template <int D>
std::int64_t leaf_bound(int d) {
  std::int64_t five = 1;
  for (int a = 0; a < D; ++a) five *= 5;
  return d * five * ((1 << D) - 1) + 1;
}

TYPED_TEST(TreeBalance, PointRefinementBalancesWithLinearSize) {
  constexpr int D = TypeParam::value;
  std::vector<std::int64_t> counts;
  for (int depth : {4, 7, 10}) {
    auto t = test::unit_tree<D>();
    refine_at<D>(t, probe<D>(), depth);
    // Unbalanced before: the last split cell is a corner child of its parent, so its
    // children touch boxes at least two levels larger across the parent's faces.
    EXPECT_GE(worst_gap(t), 2);
    const std::int64_t splits = t.balance_all();
    EXPECT_GT(splits, 0);
    EXPECT_EQ(worst_gap(t), 1) << depth;
    EXPECT_LE(t.leaf_count(), leaf_bound<D>(depth)) << depth;
    EXPECT_EQ(t.leaf_count(), static_cast<std::int32_t>(t.leaves().size()));
    // A second pass has nothing to do.
    EXPECT_EQ(t.balance_all(), 0);
    counts.push_back(t.leaf_count());
  }
  // Linear growth: each extra level adds at most 5^D (2^D - 1) leaves.
  EXPECT_LE(counts[2] - counts[1], leaf_bound<D>(3) - 1);
  EXPECT_LE(counts[1] - counts[0], leaf_bound<D>(3) - 1);
}

// Deeper refinement, checked through the tree's own neighbour query (brute force over
// pairs would be slow): the bound still holds at depth 20.
TYPED_TEST(TreeBalance, DeepPointRefinement) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  refine_at<D>(t, probe<D>(), 20);
  t.balance_all();
  EXPECT_LE(t.leaf_count(), leaf_bound<D>(20));
  std::vector<std::int32_t> nb;
  for (std::int32_t n : test::live_leaves(t)) {
    t.neighbours(n, nb);
    for (std::int32_t m : nb) ASSERT_LE(std::abs(t.level(n) - t.level(m)), 1);
  }
}

// A protected box next to the refined region is never split, although without the
// protection balance would split it (checked on an identical unprotected tree).
TYPED_TEST(TreeBalance, ProtectedLeavesAreNotSplit) {
  constexpr int D = TypeParam::value;
  auto build = [](bool protect) {
    auto t = test::unit_tree<D>();
    test::refine_uniform(t, 2);
    std::array<std::int64_t, D> c{};
    c.fill(1);
    c[0] = 2;  // x in [1/2, 3/4], next to the probe's cell x in [1/4, 1/2]
    const std::int32_t p = test::at_cell(t, 2, c);
    t.set_protected(p, protect);
    std::array<double, D> pt = probe<D>();
    pt[0] = 0.45;  // 0.05 from the protected box's face
    refine_at<D>(t, pt, 9);
    t.balance_all();
    return std::pair{std::move(t), p};
  };
  auto [prot, p] = build(true);
  EXPECT_TRUE(prot.is_leaf(p));
  EXPECT_TRUE(prot.is_protected(p));
  EXPECT_EQ(worst_gap(prot, p), 1);  // everything else is balanced
  int gap = 0;
  for (std::int32_t m : prot.neighbours(p)) gap = std::max(gap, prot.level(m) - prot.level(p));
  EXPECT_GE(gap, 2);  // the protected box really violates the condition
  auto [unprot, q] = build(false);
  EXPECT_FALSE(unprot.is_leaf(q));
  EXPECT_EQ(worst_gap(unprot), 1);
}

TYPED_TEST(TreeBalance, CallbackDecidesBalanceAdjacency) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  refine_at<D>(t, probe<D>(), 6);
  const std::int32_t before = t.size();
  int calls = 0;
  EXPECT_EQ(t.balance_all([&](std::int32_t big, std::int32_t small) {
    ++calls;
    EXPECT_LT(t.level(big), t.level(small) - 1);
    return false;
  }),
            0);
  EXPECT_GT(calls, 0);
  EXPECT_EQ(t.size(), before);
  // Only boxes in the lower half x < 1/2 count as adjacent: the upper half is left
  // alone, the lower half gets balanced.
  t.balance_all([&](std::int32_t big, std::int32_t) { return t.plane(big, 0, true) <= 0.5; });
  for (std::int32_t n : test::live_leaves(t)) {
    if (t.plane(n, 0, true) > 0.5) continue;
    for (std::int32_t m : t.neighbours(n))
      if (t.plane(m, 0, true) <= 0.5) {
        EXPECT_LE(std::abs(t.level(n) - t.level(m)), 1);
      }
  }
  const std::int32_t upper = t.find(BoxKey<D>::cell(1, [] {
    std::array<std::int64_t, D> c{};
    c[0] = 1;
    return c;
  }()));
  EXPECT_TRUE(t.is_leaf(upper));
}

// The split hook sees every split with its first child, and duplicates it creates
// join the worklist: the final tree, duplicates included, is balanced.
TYPED_TEST(TreeBalance, SplitHookAndDuplicates) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  refine_at<D>(t, probe<D>(), 7);
  std::int64_t hooks = 0;
  const std::int64_t splits = t.balance_all([](std::int32_t, std::int32_t) { return true; },
                                            [&](std::int32_t node, std::int32_t first) {
                                              ++hooks;
                                              EXPECT_EQ(t.first_child(node), first);
                                              t.duplicate(first, 1);  // a second component in child 0
                                            });
  EXPECT_EQ(hooks, splits);
  EXPECT_GT(splits, 0);
  EXPECT_EQ(worst_gap(t), 1);
}

// A merged (vertex-centering) box is never split by balance.
TYPED_TEST(TreeBalance, MergedBoxesAreExempt) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 2);
  std::vector<std::int32_t> block;
  for (int k = 0; k < (1 << D); ++k) {
    std::array<std::int64_t, D> c{};
    for (int a = 0; a < D; ++a) c[a] = 1 + ((k >> a) & 1);
    block.push_back(test::at_cell(t, 2, c));
  }
  const std::int32_t m = t.merge(block);
  t.set_protected(m, false);  // still exempt: merged boxes cannot be split
  std::array<double, D> pt{};
  pt.fill(0.3);
  pt[0] = 0.8;  // outside the merged box [1/4, 3/4]^D
  refine_at<D>(t, pt, 7);
  t.balance_all();
  EXPECT_TRUE(t.is_leaf(m));
  EXPECT_EQ(worst_gap(t, m), 1);
}

// Same operations, same ids: two trees built from one random script agree node by
// node and in leaf order.
template <int D>
Tree<D> scripted(std::uint64_t seed) {
  auto t = test::unit_tree<D>();
  std::mt19937_64 rng(seed);
  for (int op = 0; op < 80; ++op) {
    const auto ls = t.leaves();
    const std::int32_t n = ls[rng() % ls.size()];
    if (rng() % 4 == 0)
      t.duplicate(n, 1);
    else if (!t.is_merged(n) && t.level(n) < 8)
      t.split(n);
  }
  t.balance_all([](std::int32_t, std::int32_t) { return true; },
                [&](std::int32_t, std::int32_t first) {
                  if (first % 5 == 0) t.duplicate(first, 2);
                });
  return t;
}

TYPED_TEST(TreeBalance, Deterministic) {
  constexpr int D = TypeParam::value;
  const auto a = scripted<D>(99), b = scripted<D>(99);
  ASSERT_EQ(a.size(), b.size());
  for (std::int32_t n = 0; n < a.size(); ++n) {
    ASSERT_EQ(a.key(n), b.key(n));
    ASSERT_EQ(a.state(n), b.state(n));
    ASSERT_EQ(a.parent(n), b.parent(n));
    ASSERT_EQ(a.first_child(n), b.first_child(n));
    ASSERT_EQ(a.next_same_key(n), b.next_same_key(n));
    ASSERT_EQ(a.component(n), b.component(n));
  }
  EXPECT_EQ(a.leaves(), b.leaves());
  EXPECT_EQ(worst_gap(a), 1);
}

}  // namespace
}  // namespace pqmesh
