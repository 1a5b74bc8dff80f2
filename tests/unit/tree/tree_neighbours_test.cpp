// Neighbour, overlap and point queries: hand-counted configurations plus a randomized
// comparison against brute-force oracles (tree_test_util.hpp) that look at box
// planes only.
#include <random>

#include "tree_test_util.hpp"

namespace pqmesh {
namespace {

using test::Dims;

template <class T>
class TreeNeighbours : public ::testing::Test {};
TYPED_TEST_SUITE(TreeNeighbours, Dims);

template <int D>
std::array<std::int64_t, D> filled(std::int64_t v) {
  std::array<std::int64_t, D> c{};
  c.fill(v);
  return c;
}

int ipow(int b, int e) {
  int r = 1;
  for (int i = 0; i < e; ++i) r *= b;
  return r;
}

// Uniform level-3 grid (8^D cells). A cell with k coordinates on the root boundary
// (0 or 7) has 2^k * 3^(D-k) - 1 neighbours: per axis 2 choices instead of 3. The
// neighbour set must be exactly the cells at Chebyshev distance 1.
TYPED_TEST(TreeNeighbours, UniformGridCounts) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 3);
  for (std::int32_t n : t.leaves()) {
    int k = 0;
    std::array<std::int64_t, D> c{};
    for (int a = 0; a < D; ++a) {
      c[a] = t.key(n).q[a] / 2;
      k += (c[a] == 0 || c[a] == 7) ? 1 : 0;
    }
    const auto nb = t.neighbours(n);
    ASSERT_EQ(static_cast<int>(nb.size()), ipow(2, k) * ipow(3, D - k) - 1) << n;
    for (std::int32_t m : nb) {
      EXPECT_EQ(t.level(m), 3);
      std::int64_t cheb = 0;
      for (int a = 0; a < D; ++a) cheb = std::max(cheb, std::abs(t.key(m).q[a] / 2 - c[a]));
      EXPECT_EQ(cheb, 1);
    }
  }
  // Interior: 3^D - 1 (8 and 26); corner: 2^D - 1 (3 and 7).
  EXPECT_EQ(t.neighbours(test::at_cell(t, 3, filled<D>(4))).size(), static_cast<std::size_t>(ipow(3, D) - 1));
  EXPECT_EQ(t.neighbours(test::at_cell(t, 3, filled<D>(0))).size(), static_cast<std::size_t>(ipow(2, D) - 1));
}

TYPED_TEST(TreeNeighbours, RootHasNoNeighbours) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  EXPECT_TRUE(t.neighbours(0).empty());
  std::vector<std::int32_t> out;
  t.overlapping(0, out);
  EXPECT_TRUE(out.empty());
}

// Level-2 grid; cell c = (1,1,..). Split its +x face neighbour (2,1,..) and its
// all-plus corner neighbour (2,2,..). By hand: c keeps the 3^D - 1 - 2 unsplit
// same-size neighbours, gains the 2^(D-1) children of the face neighbour that lie on
// the shared face, and exactly one child (the all-minus one) of the corner neighbour.
TYPED_TEST(TreeNeighbours, BigLeafNextToSmallOnes) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 2);
  const std::int32_t c = test::at_cell(t, 2, filled<D>(1));
  auto face = filled<D>(1);
  face[0] = 2;
  const std::int32_t f = t.split(test::at_cell(t, 2, face));
  const std::int32_t g = t.split(test::at_cell(t, 2, filled<D>(2)));
  const auto nb = t.neighbours(c);
  EXPECT_EQ(static_cast<int>(nb.size()), ipow(3, D) - 3 + (1 << (D - 1)) + 1);
  for (int k = 0; k < (1 << D); ++k) {
    const bool face_child_touches = (k & 1) == 0;  // lower x half
    EXPECT_EQ(std::binary_search(nb.begin(), nb.end(), f + k), face_child_touches) << k;
    EXPECT_EQ(std::binary_search(nb.begin(), nb.end(), g + k), k == 0) << k;
    // Conversely the small boxes see the big one.
    const auto back = t.neighbours(f + k);
    EXPECT_EQ(std::binary_search(back.begin(), back.end(), c), face_child_touches);
  }
  std::vector<std::int32_t> larger;
  t.larger_neighbours(f, larger);  // child 0 of the face neighbour: c is larger
  EXPECT_TRUE(std::binary_search(larger.begin(), larger.end(), c));
  for (std::int32_t m : larger) EXPECT_LT(t.level(m), t.level(f));
  t.larger_neighbours(c, larger);
  EXPECT_TRUE(larger.empty());
  for (std::int32_t n : test::live_leaves(t)) EXPECT_EQ(t.neighbours(n), test::brute_neighbours(t, n)) << n;
}

// Duplicates: d duplicates cell c. They are not each other's neighbours (they
// overlap), have the same other neighbours, and both appear as neighbours of e.
TYPED_TEST(TreeNeighbours, DuplicatesAreNotNeighboursOfEachOther) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 2);
  const std::int32_t c = test::at_cell(t, 2, filled<D>(1));
  const std::int32_t d = t.duplicate(c, 1);
  auto ecell = filled<D>(1);
  ecell[0] = 2;
  const std::int32_t e = test::at_cell(t, 2, ecell);
  auto nc = t.neighbours(c), nd = t.neighbours(d), ne = t.neighbours(e);
  EXPECT_FALSE(std::binary_search(nc.begin(), nc.end(), d));
  EXPECT_FALSE(std::binary_search(nd.begin(), nd.end(), c));
  EXPECT_EQ(nc, nd);
  EXPECT_EQ(static_cast<int>(nc.size()), ipow(3, D) - 1);
  EXPECT_TRUE(std::binary_search(ne.begin(), ne.end(), c));
  EXPECT_TRUE(std::binary_search(ne.begin(), ne.end(), d));
  std::vector<std::int32_t> ov;
  t.overlapping(c, ov);
  EXPECT_EQ(ov, std::vector<std::int32_t>{d});
  // The lower corner of c is shared by 2^D level-2 cells, plus the duplicate d.
  const auto at_corner = t.leaves_containing(t.box(c).lo);
  EXPECT_EQ(static_cast<int>(at_corner.size()), (1 << D) + 1);
  EXPECT_EQ(at_corner, test::brute_containing(t, t.box(c).lo));

  // Split the duplicate: its children overlap c (not neighbours of c), and the ones
  // on the +x side are neighbours of e (d itself is gone).
  const std::int32_t dc = t.split(d);
  nc = t.neighbours(c);
  ne = t.neighbours(e);
  t.overlapping(c, ov);
  EXPECT_EQ(static_cast<int>(ov.size()), 1 << D);
  for (int k = 0; k < (1 << D); ++k) {
    EXPECT_FALSE(std::binary_search(nc.begin(), nc.end(), dc + k));
    EXPECT_EQ(ov[static_cast<std::size_t>(k)], dc + k);
    EXPECT_EQ(std::binary_search(ne.begin(), ne.end(), dc + k), (k & 1) == 1) << k;
  }
  EXPECT_FALSE(std::binary_search(ne.begin(), ne.end(), d));
  for (std::int32_t n : test::live_leaves(t)) {
    EXPECT_EQ(t.neighbours(n), test::brute_neighbours(t, n)) << n;
    t.overlapping(n, ov);
    EXPECT_EQ(ov, test::brute_overlapping(t, n)) << n;
  }
}

// A leaf duplicate B2 of a level-1 cell whose other duplicate B1 is split: a small
// box b just across the x = 1/2 plane must see B2 although the first keys found
// walking up from b's neighbour cell belong to B1's subtree.
TYPED_TEST(TreeNeighbours, DuplicateAboveASplitDuplicateIsFound) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  const std::int32_t r = t.split(0);
  const std::int32_t b1 = r + 1;  // cell (1, 0, ..): x in [1/2, 1]
  const std::int32_t b2 = t.duplicate(b1, 1);
  t.split(b1);
  const std::int32_t a = t.split(r + 0);  // level 2 in [0, 1/2]^D
  const std::int32_t a1 = t.split(a + 1);  // level-2 cell (1, 0, ..): x in [1/4, 1/2]
  const std::int32_t b = a1 + 1;           // level-3 cell (3, 0, ..): x in [3/8, 1/2]
  EXPECT_EQ(t.plane(b, 0, true), 0.5);
  const auto nb = t.neighbours(b);
  EXPECT_TRUE(std::binary_search(nb.begin(), nb.end(), b2));
  EXPECT_EQ(nb, test::brute_neighbours(t, b));
}

// Vertex centering merge (thesis §4.1.3): a 2^D block of level-3 cells starting at
// the odd cell (3,3,..) becomes one leaf of level 2 whose origin 3/8 is not on the
// level-2 grid. Its neighbours are the 4^D - 2^D level-3 cells around the block.
TYPED_TEST(TreeNeighbours, UnalignedMerge) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 3);
  std::vector<std::int32_t> block;
  for (int k = 0; k < (1 << D); ++k) {
    auto c = filled<D>(3);
    for (int a = 0; a < D; ++a) c[a] += (k >> a) & 1;
    block.push_back(test::at_cell(t, 3, c));
  }
  const std::int32_t m = t.merge(block, 0);
  EXPECT_TRUE(t.is_merged(m));
  EXPECT_TRUE(t.is_leaf(m));
  EXPECT_TRUE(t.is_protected(m));
  EXPECT_EQ(t.level(m), 2);
  EXPECT_FALSE(t.key(m).aligned());
  EXPECT_EQ(t.side(m), 0.25);
  for (int a = 0; a < D; ++a) {
    EXPECT_EQ(t.plane(m, a, false), 0.375);
    EXPECT_EQ(t.plane(m, a, true), 0.625);
  }
  for (std::int32_t b : block) {
    EXPECT_EQ(t.state(b), BoxState::Absorbed);
    EXPECT_EQ(t.absorbed_into(b), m);
  }
  EXPECT_EQ(t.leaf_count(), ipow(8, D) - (1 << D) + 1);
  const auto nm = t.neighbours(m);
  EXPECT_EQ(static_cast<int>(nm.size()), ipow(4, D) - ipow(2, D));
  // Cell (2,2,..) touches the block only at its corner (3/8, ..).
  const auto n22 = t.neighbours(test::at_cell(t, 3, filled<D>(2)));
  EXPECT_TRUE(std::binary_search(n22.begin(), n22.end(), m));
  EXPECT_EQ(static_cast<int>(n22.size()), ipow(3, D) - 1);
  std::array<double, D> centre{};
  centre.fill(0.5);
  EXPECT_EQ(t.leaves_containing(centre), std::vector<std::int32_t>{m});
  EXPECT_THROW(t.split(m), InternalError);
  for (std::int32_t n : test::live_leaves(t)) EXPECT_EQ(t.neighbours(n), test::brute_neighbours(t, n)) << n;
  EXPECT_EQ(t.leaves().size(), static_cast<std::size_t>(t.leaf_count()));
}

// An aligned merge (the four/eight children of one split cell, plus a duplicate of one
// of them; the other duplicate stays a leaf overlapping the merged box).
TYPED_TEST(TreeNeighbours, AlignedMergeWithDuplicates) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 2);
  const std::int32_t p = test::at_cell(t, 2, filled<D>(1));
  const std::int32_t f = t.split(p);
  const std::int32_t dup_in = t.duplicate(f + 0, 1);
  const std::int32_t dup_out = t.duplicate(f + 1, 1);
  std::vector<std::int32_t> block{dup_in};
  for (int k = 0; k < (1 << D); ++k) block.push_back(f + k);
  const std::int32_t m = t.merge(block, 0);
  EXPECT_TRUE(t.key(m).aligned());
  EXPECT_EQ(t.key(m), t.key(p));
  EXPECT_EQ(t.find(t.key(m)), p);  // same key list as the split parent
  EXPECT_EQ(t.next_same_key(p), m);
  std::vector<std::int32_t> ov;
  t.overlapping(m, ov);
  EXPECT_EQ(ov, std::vector<std::int32_t>{dup_out});
  for (std::int32_t n : test::live_leaves(t)) {
    EXPECT_EQ(t.neighbours(n), test::brute_neighbours(t, n)) << n;
    t.overlapping(n, ov);
    EXPECT_EQ(ov, test::brute_overlapping(t, n)) << n;
  }
  // Duplicating the merged box gives another merged, protected leaf of the same cube.
  const std::int32_t m2 = t.duplicate(m, 2);
  EXPECT_TRUE(t.is_merged(m2));
  EXPECT_TRUE(t.is_protected(m2));
  for (std::int32_t n : test::live_leaves(t)) EXPECT_EQ(t.neighbours(n), test::brute_neighbours(t, n)) << n;
}

TYPED_TEST(TreeNeighbours, MergeRejectsBadBlocks) {
  constexpr int D = TypeParam::value;
  auto t = test::unit_tree<D>();
  test::refine_uniform(t, 2);
  std::vector<std::int32_t> block;
  for (int k = 0; k < (1 << D); ++k) {
    auto c = filled<D>(0);
    for (int a = 0; a < D; ++a) c[a] += 2 * ((k >> a) & 1);  // spread out: not a 2^D block
    block.push_back(test::at_cell(t, 2, c));
  }
  EXPECT_THROW(t.merge(block), InternalError);
  block.assign(static_cast<std::size_t>(1 << D), test::at_cell(t, 2, filled<D>(0)));
  EXPECT_THROW(t.merge(block), InternalError);  // repeated id
  block.resize(1);
  EXPECT_THROW(t.merge(block), InternalError);  // too few
  block.clear();
  for (int k = 0; k < (1 << D); ++k) block.push_back(k + 1);  // level-1 boxes: split, not leaves
  EXPECT_THROW(t.merge(block), InternalError);
}

// Randomized: splits, duplicates and (when allowed) merges, aligned and not, in any
// order; every query is compared with the brute-force oracle. Without merges the
// larger-neighbour query takes its fast path (parent-level cells only).
template <int D>
void random_against_oracle(std::uint64_t seed, int ops, bool merges) {
  auto t = test::unit_tree<D>();
  std::mt19937_64 rng(seed);
  std::vector<std::int32_t> out;
  for (int op = 0; op < ops; ++op) {
    const auto ls = test::live_leaves(t);
    const std::int32_t n = ls[rng() % ls.size()];
    const int kind = static_cast<int>(rng() % 10);
    if (kind < 6) {
      if (!t.is_merged(n) && t.level(n) < 6) t.split(n);
    } else if (kind < 8) {
      t.duplicate(n, static_cast<std::int32_t>(rng() % 3));
    } else if (merges && !t.is_merged(n) && t.level(n) >= 1) {
      // Try the 2^D block with n at a random corner; every cell needs a leaf.
      std::array<std::int64_t, D> c0{};
      for (int a = 0; a < D; ++a) c0[a] = t.key(n).q[a] / 2 - static_cast<std::int64_t>(rng() % 2);
      std::vector<std::int32_t> block;
      bool ok = true;
      for (int k = 0; k < (1 << D) && ok; ++k) {
        std::array<std::int64_t, D> c{};
        for (int a = 0; a < D; ++a) c[a] = c0[a] + ((k >> a) & 1);
        std::int32_t pick = -1;
        if (std::all_of(c.begin(), c.end(), [&](std::int64_t v) { return v >= 0 && v < (1 << t.level(n)); }))
          for (std::int32_t x = test::at_cell(t, t.level(n), c); x >= 0; x = t.next_same_key(x))
            if (t.is_leaf(x) && !t.is_merged(x) && pick < 0) pick = x;
        ok = pick >= 0;
        block.push_back(pick);
      }
      if (ok) t.merge(block, 0);
    }
  }
  const auto ls = test::live_leaves(t);
  ASSERT_EQ(static_cast<std::int32_t>(ls.size()), t.leaf_count());
  for (std::int32_t n : ls) {
    t.neighbours(n, out);
    ASSERT_EQ(out, test::brute_neighbours(t, n)) << "seed " << seed << " node " << n;
    t.overlapping(n, out);
    ASSERT_EQ(out, test::brute_overlapping(t, n)) << "seed " << seed << " node " << n;
    t.larger_neighbours(n, out);
    auto big = test::brute_neighbours(t, n);
    std::erase_if(big, [&](std::int32_t m) { return t.level(m) >= t.level(n); });
    ASSERT_EQ(out, big) << "seed " << seed << " node " << n;
  }
  // Points on the 1/64 grid (often on box planes, edges and corners) and random ones.
  std::uniform_int_distribution<int> g(0, 64);
  std::uniform_real_distribution<double> u(-0.01, 1.01);
  for (int i = 0; i < 200; ++i) {
    std::array<double, D> p{};
    for (int a = 0; a < D; ++a) p[a] = i % 2 ? g(rng) / 64.0 : u(rng);
    t.leaves_containing(p, out);
    ASSERT_EQ(out, test::brute_containing(t, p)) << "seed " << seed;
  }
}

TYPED_TEST(TreeNeighbours, RandomTreesMatchBruteForce) {
  constexpr int D = TypeParam::value;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) random_against_oracle<D>(seed, D == 2 ? 120 : 60, seed % 2 == 1);
}

}  // namespace
}  // namespace pqmesh
