// Keys, splitting, exact planes, the root cube choice, leaf order.
#include <cmath>
#include <random>

#include "tree_test_util.hpp"

namespace pqmesh {
namespace {

using test::Dims;

template <class T>
class TreeKey : public ::testing::Test {};
TYPED_TEST_SUITE(TreeKey, Dims);

TYPED_TEST(TreeKey, SplitGivesContiguousChildrenWithChildKeys) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  ASSERT_EQ(t.size(), 1);
  EXPECT_TRUE(t.is_leaf(0));
  EXPECT_EQ(t.parent(0), -1);
  const std::int32_t first = t.split(0);
  EXPECT_EQ(first, 1);
  EXPECT_EQ(t.state(0), BoxState::Split);
  EXPECT_EQ(t.first_child(0), 1);
  EXPECT_EQ(t.leaf_count(), 1 << D);
  for (int k = 0; k < (1 << D); ++k) {
    const std::int32_t c = first + k;
    EXPECT_EQ(t.parent(c), 0);
    EXPECT_EQ(t.level(c), 1);
    EXPECT_TRUE(t.key(c).aligned());
    EXPECT_EQ(t.find(t.key(c)), c);
    EXPECT_EQ(t.side(c), 0.5);
    // Bit a of k selects the upper half along axis a.
    for (int a = 0; a < D; ++a) {
      const bool up = (k >> a) & 1;
      EXPECT_EQ(t.plane(c, a, false), up ? 0.5 : 0.0);
      EXPECT_EQ(t.plane(c, a, true), up ? 1.0 : 0.5);
    }
  }
  EXPECT_THROW(t.split(0), InternalError);  // not a leaf any more
}

// split() hashes child 0 only and derives its siblings' hashes (key.hpp
// sibling_hash); that must equal hashing each child key on its own, for random
// aligned keys at shallow and deep levels (q up to 2^(level+1)).
TYPED_TEST(TreeKey, SiblingHashEqualsTheChildsOwnHash) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    BoxKey<D> k;
    k.level = static_cast<std::int32_t>(rng() % kTreeMaxLevel);
    for (int a = 0; a < D; ++a) k.q[a] = 2 * static_cast<std::int64_t>(rng() % (std::uint64_t{1} << k.level));
    const detail::KeyHash h0 = detail::hash_key(k.child(0));
    for (int c = 0; c < (1 << D); ++c) {
      const detail::KeyHash own = detail::hash_key(k.child(c));
      const detail::KeyHash sib = detail::sibling_hash(h0, static_cast<unsigned>(c));
      ASSERT_EQ(sib.pos, own.pos) << "level " << k.level << " child " << c;
      ASSERT_EQ(sib.tag, own.tag) << "level " << k.level << " child " << c;
    }
  }
}

// prefetch_split is a hint: it accepts any id and changes nothing.
TYPED_TEST(TreeKey, PrefetchSplitChangesNothing) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  t.prefetch_split(-1);
  t.prefetch_split(5);
  t.prefetch_split(0);
  EXPECT_EQ(t.size(), 1);
  const std::int32_t first = t.split(0);
  for (int c = 0; c < (1 << D); ++c) EXPECT_EQ(t.find(t.key(first + c)), first + c);
}

// reserve() jumps the key index straight to its final capacity (several doublings
// at once) with keys already in it: every key must still be found, and the tree
// must be the one built without the reservation (same ids and keys).
TYPED_TEST(TreeKey, ReserveKeepsKeysAndIds) {
  constexpr int D = TypeParam::value;
  auto plain = test::unit_tree<D>();
  auto reserved = test::unit_tree<D>();
  test::refine_uniform(plain, 2);
  test::refine_uniform(reserved, 2);
  reserved.reserve(1 << 16);  // 64 slots -> 2^17: eleven doublings in one step
  for (std::int32_t n = 0; n < reserved.size(); ++n) EXPECT_EQ(reserved.find(reserved.key(n)), n);
  test::refine_uniform(plain, D == 2 ? 5 : 3);
  test::refine_uniform(reserved, D == 2 ? 5 : 3);
  ASSERT_EQ(plain.size(), reserved.size());
  for (std::int32_t n = 0; n < reserved.size(); ++n) {
    EXPECT_EQ(reserved.key(n), plain.key(n));
    EXPECT_EQ(reserved.find(plain.key(n)), n);
  }
}

// Root [-2, 2] x [4, 8] (x [-2, 2]): origin is a multiple of size/2 = 2. The level-3
// cell (5, 3, 1) spans, by hand: x = -2 + 4*5/8 = 0.5 .. 1.0, y = 4 + 4*3/8 = 5.5 ..
// 6.0, z = -2 + 4*1/8 = -1.5 .. -1.0.
TYPED_TEST(TreeKey, PlanesOfAnOffsetRoot) {
  constexpr int D = TypeParam::value;
  RootCube<D> root;
  root.size = 4;
  root.origin[0] = -2;
  root.origin[1] = 4;
  if constexpr (D == 3) root.origin[2] = -2;
  Tree<D> t(root);
  test::refine_uniform(t, 3);
  std::array<std::int64_t, D> cell{};
  cell[0] = 5;
  cell[1] = 3;
  if constexpr (D == 3) cell[2] = 1;
  const std::int32_t n = test::at_cell(t, 3, cell);
  ASSERT_GE(n, 0);
  const auto b = t.box(n);
  EXPECT_EQ(b.lo[0], 0.5);
  EXPECT_EQ(b.hi[0], 1.0);
  EXPECT_EQ(b.lo[1], 5.5);
  EXPECT_EQ(b.hi[1], 6.0);
  if constexpr (D == 3) {
    EXPECT_EQ(b.lo[2], -1.5);
    EXPECT_EQ(b.hi[2], -1.0);
  }
  EXPECT_EQ(t.side(n), 0.5);
}

// ex(b) by hand: the level-2 cell (1, 2, ..): [1/4, 1/2] x [1/2, 3/4] (x [1/2, 3/4]); side 1/4, so ex(b) is
// [1/4 - 1/2, 1/2 + 1/2] = [-1/4, 1] along x and [0, 5/4] along the other axes.
TYPED_TEST(TreeKey, ExtendedBoxIsFiveTimesTheCube) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 2);
  std::array<std::int64_t, D> c{};
  c.fill(2);
  c[0] = 1;
  const auto ex = t.extended_box(test::at_cell(t, 2, c));
  EXPECT_EQ(ex.lo[0], -0.25);
  EXPECT_EQ(ex.hi[0], 1.0);
  for (int a = 1; a < D; ++a) {
    EXPECT_EQ(ex.lo[a], 0.0);
    EXPECT_EQ(ex.hi[a], 1.25);
  }
}

// For root [0, 1], the lower plane of cell i at level L is exactly i / 2^L: scaling
// by 2^L (exact) must give back the integer i, at every level down to max_level().
TYPED_TEST(TreeKey, PlanesAreExactAtEveryLevel) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  EXPECT_EQ(t.max_level(), kTreeMaxLevel);
  for (int lev = 0; lev <= t.max_level(); ++lev) {
    const std::int64_t top = std::int64_t{1} << lev;
    for (std::int64_t i : {std::int64_t{0}, top / 3, top / 2 + 1, top - 1}) {
      if (i < 0 || i >= top) continue;
      std::array<std::int64_t, D> c{};
      c.fill(i);
      const auto k = BoxKey<D>::cell(lev, c);
      const double lo = t.key_plane(k, 0, false), hi = t.key_plane(k, D - 1, true);
      EXPECT_EQ(std::ldexp(lo, lev), static_cast<double>(i)) << lev;
      EXPECT_EQ(std::ldexp(hi, lev), static_cast<double>(i + 1)) << lev;
      EXPECT_LT(lo, hi);
    }
  }
}

// A root far from the origin leaves fewer bits for levels: origin 2^40 with size 1
// means m = origin / (1/2) = 2^41, and planes need (m + 2) * 2^L <= 2^53, so L <= 11.
TYPED_TEST(TreeKey, MaxLevelShrinksForFarRoots) {
  constexpr int D = TypeParam::value;
  RootCube<D> root;
  root.size = 1;
  root.origin.fill(0x1p40);
  Tree<D> t(root);
  EXPECT_EQ(t.max_level(), 11);
  std::int32_t n = 0;
  for (int l = 0; l < 11; ++l) n = t.split(n);
  EXPECT_EQ(t.level(n), 11);
  EXPECT_EQ(t.plane(n, 0, false), 0x1p40);  // child 0 all the way down
  EXPECT_EQ(t.plane(n, 0, true), 0x1p40 + 0x1p-11);
  EXPECT_THROW(t.split(n), InternalError);
}

TYPED_TEST(TreeKey, RejectsBadRoots) {
  constexpr int D = TypeParam::value;
  RootCube<D> r;
  r.size = 3;  // not a power of two
  EXPECT_THROW(Tree<D>{r}, InternalError);
  r.size = 4;
  r.origin[0] = 1;  // not a multiple of 2
  EXPECT_THROW(Tree<D>{r}, InternalError);
  r.origin[0] = 2;
  EXPECT_NO_THROW(Tree<D>{r});
}

// Hand-derived: bbox [-1, 1]^D, margin 0.25 * 2 = 0.5, wanted [-1.5, 1.5], span 3 ->
// size 4, half 2, origin floor(-1.5 / 2) * 2 = -2, top 2 >= 1.5.
TYPED_TEST(TreeKey, ChooseRootCubeStraddlingZero) {
  constexpr int D = TypeParam::value;
  std::array<double, D> lo{}, hi{};
  lo.fill(-1);
  hi.fill(1);
  const auto r = choose_root_cube<D>(lo, hi);
  EXPECT_EQ(r.size, 4);
  for (int a = 0; a < D; ++a) EXPECT_EQ(r.origin[a], -2);
}

// Hand-derived: bbox x [0.1, 0.9], y [0.2, 0.3]: extent 0.8, margin 0.2, wanted
// x [-0.1, 1.1], y [0, 0.5]; span 1.2 -> size 2 (half 1): x origin -1, top 1 < 1.1
// fails -> size 4 (half 2): x origin -2 (top 2), y origin 0 (0 < 0.2, top 4).
TEST(TreeKey2, ChooseRootCubeDoublesWhenTheGridIsUnlucky) {
  const auto r = choose_root_cube<2>({0.1, 0.2}, {0.9, 0.3});
  EXPECT_EQ(r.size, 4);
  EXPECT_EQ(r.origin[0], -2);
  EXPECT_EQ(r.origin[1], 0);
}

// Property: for random boxes the root is a power of two, its origin a multiple of
// half of it, and the box strictly inside.
TYPED_TEST(TreeKey, ChooseRootCubeEnclosesStrictly) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(-1000, 1000), ext(1e-3, 50);
  for (int it = 0; it < 500; ++it) {
    std::array<double, D> lo{}, hi{};
    for (int a = 0; a < D; ++a) {
      lo[a] = pos(rng);
      hi[a] = lo[a] + ext(rng);
    }
    const auto r = choose_root_cube<D>(lo, hi);
    int e = 0;
    EXPECT_EQ(std::frexp(r.size, &e), 0.5);
    for (int a = 0; a < D; ++a) {
      EXPECT_LT(r.origin[a], lo[a]);
      EXPECT_GT(r.origin[a] + r.size, hi[a]);
      const double m = r.origin[a] / (r.size / 2);
      EXPECT_EQ(m, std::floor(m));
    }
    EXPECT_NO_THROW(Tree<D>{r});
  }
  std::array<double, D> p{};
  p.fill(3);
  const auto r = choose_root_cube<D>(p, p);  // a single point: margin 1
  for (int a = 0; a < D; ++a) {
    EXPECT_LT(r.origin[a], 3);
    EXPECT_GT(r.origin[a] + r.size, 3);
  }
}

// z-order of a uniform level-2 quadtree, axis 0 least significant, by hand:
// (0,0) (1,0) (0,1) (1,1) (2,0) (3,0) (2,1) (3,1) (0,2) (1,2) (0,3) (1,3) ...
TEST(TreeKey2, LeavesAreInZOrder) {
  auto t = test::unit_tree<2>();
  test::refine_uniform(t, 2);
  const std::vector<std::array<std::int64_t, 2>> expect = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {3, 0},
                                                           {2, 1}, {3, 1}, {0, 2}, {1, 2}, {0, 3}, {1, 3},
                                                           {2, 2}, {3, 2}, {2, 3}, {3, 3}};
  const auto ls = t.leaves();
  ASSERT_EQ(ls.size(), expect.size());
  for (std::size_t i = 0; i < ls.size(); ++i) EXPECT_EQ(t.key(ls[i]), (BoxKey<2>::cell(2, expect[i]))) << i;
}

// Mixed levels: after splitting the root and then child 0, the z-order is child 0's
// four children (ids 5..8), then children 1, 2, 3 (ids 2, 3, 4). A duplicate of id 3
// with component 1 comes right after id 3; a larger box precedes a smaller one with
// the same origin.
TEST(TreeKey2, LeafOrderWithLevelsAndDuplicates) {
  auto t = test::unit_tree<2>();
  t.split(0);
  t.split(1);
  const std::int32_t dup = t.duplicate(3, 1);  // id 9
  EXPECT_EQ(dup, 9);
  const auto ls = t.leaves();
  EXPECT_EQ(ls, (std::vector<std::int32_t>{5, 6, 7, 8, 2, 3, 9, 4}));
  EXPECT_EQ(t.leaf_count(), 8);
  EXPECT_EQ(t.find(t.key(3)), 3);
  EXPECT_EQ(t.next_same_key(3), 9);
  EXPECT_EQ(t.next_same_key(9), -1);
  EXPECT_EQ(t.parent(9), 0);
  EXPECT_EQ(t.component(9), 1);
}

TEST(TreeKey2, PayloadAndProtectionDefaults) {
  auto t = test::unit_tree<2>();
  const std::int32_t f = t.split(0);
  EXPECT_EQ(t.payload(f), -1);
  EXPECT_EQ(t.component(f), 0);
  EXPECT_FALSE(t.is_protected(f));
  t.set_payload(f, 42);
  t.set_protected(f, true);
  t.set_component(f, 3);
  EXPECT_EQ(t.payload(f), 42);
  EXPECT_TRUE(t.is_protected(f));
  EXPECT_EQ(t.component(f), 3);
  t.set_protected(f, false);
  EXPECT_FALSE(t.is_protected(f));
  EXPECT_THROW(t.payload(99), InternalError);
}

}  // namespace
}  // namespace pqmesh
