// EdgeQueue (src/improve3d/edge_queue.hpp): entries leave in the order
// (length2, a, b), whether they came in the sorted start or were pushed
// during the pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "improve3d/edge_queue.hpp"

namespace pqmesh::improve3d::detail {
namespace {

bool same(const EdgeEntry& x, const EdgeEntry& y) { return x.length2 == y.length2 && x.a == y.a && x.b == y.b; }

// A pushed entry that precedes the head of the sorted start leaves first;
// equal lengths are ordered by the smaller id, then the larger.
TEST(EdgeQueue, PushedEntriesInterleaveWithTheSortedStart) {
  EdgeQueue queue;
  queue.start(EdgeList{{4, 0, 1}, {1, 2, 3}, {1, 1, 5}, {9, 0, 2}});
  EXPECT_TRUE(same(queue.pop(), {1, 1, 5}));
  queue.push({2, 0, 7});
  queue.push({1, 0, 9});  // length 1 like the head (2, 3), smaller first id
  const std::vector<EdgeEntry> expected = {{1, 0, 9}, {1, 2, 3}, {2, 0, 7}, {4, 0, 1}, {9, 0, 2}};
  for (const EdgeEntry& e : expected) {
    ASSERT_FALSE(queue.empty());
    EXPECT_TRUE(same(queue.pop(), e)) << e.length2 << " " << e.a << " " << e.b;
  }
  EXPECT_TRUE(queue.empty());
}

// Many entries (the list and the heap span many blocks): every entry leaves
// once, and in order, when each push is no earlier than the last pop (as a
// collapse's new edges are: at least as long as the collapsed one).
TEST(EdgeQueue, ManyEntriesLeaveInOrder) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> length(0, 999), id(0, 99);
  EdgeList start;
  std::vector<EdgeEntry> all;
  for (int i = 0; i < 20000; ++i) {
    const int a = id(random);
    start.push_back({static_cast<double>(length(random)), a, a + 1 + id(random)});
    all.push_back(start.back());
  }
  EdgeQueue queue;
  queue.start(start);
  std::vector<EdgeEntry> popped;
  while (!queue.empty()) {
    popped.push_back(queue.pop());
    if (popped.size() % 3 == 0 && popped.back().length2 < 990) {
      const EdgeEntry later = {popped.back().length2 + 1 + length(random) % 9, 1, 2};
      queue.push(later);
      all.push_back(later);
    }
  }
  std::sort(all.begin(), all.end(), earlier);
  ASSERT_EQ(popped.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) ASSERT_TRUE(same(popped[i], all[i])) << "entry " << i;
}

}  // namespace
}  // namespace pqmesh::improve3d::detail
