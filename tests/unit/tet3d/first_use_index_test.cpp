// FirstUseIndex (tet3d/points/first_use_index.hpp): ids in order of first insertion,
// whatever the hash and the table growth, and exact lookups.
#include "tet3d/points/first_use_index.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {
namespace {

// Grid points as the tree makes them: multiples of a large power of two (their
// low bits are all zero), here 2^30 times a small lattice point.
GridPoint lattice(std::int64_t i, std::int64_t j, std::int64_t k) {
  const std::int64_t unit = std::int64_t{1} << 30;
  return GridPoint{{i * unit, j * unit, k * unit}};
}

// Every key collides: the probe sequence and the key comparison alone decide.
struct ConstantHash {
  std::size_t operator()(const GridPoint&) const { return 42; }
};

template <class Hash>
void check_first_use_order(int side) {
  FirstUseIndex<GridPoint, Hash> index;
  std::vector<GridPoint> order;
  // A scrambled visiting order of the side^3 lattice (37 is coprime to the
  // sizes used), each point inserted twice: the second time it is not fresh.
  const int n = side * side * side;
  for (int t = 0; t < n; ++t) {
    const int c = (t * 37) % n;
    const GridPoint p = lattice(c % side, (c / side) % side, c / (side * side) - 3);
    const auto [id, fresh] = index.insert(p);
    ASSERT_TRUE(fresh);
    ASSERT_EQ(id, t);
    order.push_back(p);
    const auto [again, fresh_again] = index.insert(p);
    ASSERT_FALSE(fresh_again);
    ASSERT_EQ(again, t);
  }
  ASSERT_EQ(index.size(), n);
  // After all the growth steps every key keeps its id, and points off the
  // lattice (one fine unit away, or outside it) are absent.
  for (int id = 0; id < n; ++id) {
    EXPECT_EQ(index.find(order[static_cast<std::size_t>(id)]), id);
    EXPECT_EQ(index.key(id), order[static_cast<std::size_t>(id)]);
    GridPoint off = order[static_cast<std::size_t>(id)];
    off.f[id % 3] += 1;
    EXPECT_EQ(index.find(off), -1);
  }
  EXPECT_EQ(index.find(lattice(side, 0, 0)), -1);
}

TEST(FirstUseIndex, EmptyFindsNothing) {
  const FirstUseIndex<GridPoint, GridPointHash> index;
  EXPECT_EQ(index.size(), 0);
  EXPECT_EQ(index.find(lattice(0, 0, 0)), -1);
}

TEST(FirstUseIndex, IdsInOrderOfFirstUseAcrossGrowth) {
  // 24^3 = 13824 keys: the table (1024 slots at first) grows four times.
  check_first_use_order<GridPointHash>(24);
}

TEST(FirstUseIndex, IdsInOrderOfFirstUseWhenAllHashesCollide) {
  // 6^3 = 216 keys in one probe run: quadratic work, kept small.
  check_first_use_order<ConstantHash>(6);
}

}  // namespace
}  // namespace pqmesh::tet3d
