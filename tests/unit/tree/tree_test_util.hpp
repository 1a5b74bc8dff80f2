#pragma once
// Helpers shared by the tree tests: typed-test dimension list, tree builders, and
// brute-force oracles that decide adjacency from the exact box planes alone (no key
// arithmetic, no hash lookups), so they are independent of the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "tree/tree.hpp"

namespace pqmesh::test {

using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;

template <int D>
Tree<D> unit_tree() {
  RootCube<D> root;  // [0, 1]^D
  root.size = 1;
  return Tree<D>(root);
}

// Splits every leaf until all leaves are at `level` (no duplicates).
template <int D>
void refine_uniform(Tree<D>& t, int level) {
  for (int l = 0; l < level; ++l) {
    const std::vector<std::int32_t> ls = t.leaves();
    for (std::int32_t n : ls) t.split(n);
  }
}

// The first node with the tree-aligned key of `cell` at `level` (-1 if none).
template <int D>
std::int32_t at_cell(const Tree<D>& t, int level, const std::type_identity_t<std::array<std::int64_t, D>>& cell) {
  return t.find(BoxKey<D>::cell(level, cell));
}

template <int D>
std::vector<std::int32_t> live_leaves(const Tree<D>& t) {
  std::vector<std::int32_t> out;
  for (std::int32_t n = 0; n < t.size(); ++n)
    if (t.is_leaf(n)) out.push_back(n);
  return out;
}

// Closed cubes meet.
template <int D>
bool brute_touch(const Tree<D>& t, std::int32_t a, std::int32_t b) {
  const auto x = t.box(a), y = t.box(b);
  for (int i = 0; i < D; ++i)
    if (x.lo[i] > y.hi[i] || y.lo[i] > x.hi[i]) return false;
  return true;
}

// Open cubes meet.
template <int D>
bool brute_overlap(const Tree<D>& t, std::int32_t a, std::int32_t b) {
  const auto x = t.box(a), y = t.box(b);
  for (int i = 0; i < D; ++i)
    if (x.lo[i] >= y.hi[i] || y.lo[i] >= x.hi[i]) return false;
  return true;
}

template <int D>
std::vector<std::int32_t> brute_neighbours(const Tree<D>& t, std::int32_t n) {
  std::vector<std::int32_t> out;
  for (std::int32_t m : live_leaves(t))
    if (m != n && brute_touch(t, n, m) && !brute_overlap(t, n, m)) out.push_back(m);
  return out;
}

template <int D>
std::vector<std::int32_t> brute_overlapping(const Tree<D>& t, std::int32_t n) {
  std::vector<std::int32_t> out;
  for (std::int32_t m : live_leaves(t))
    if (m != n && brute_overlap(t, n, m)) out.push_back(m);
  return out;
}

template <int D>
std::vector<std::int32_t> brute_containing(const Tree<D>& t, const typename Tree<D>::Point& p) {
  std::vector<std::int32_t> out;
  for (std::int32_t m : live_leaves(t)) {
    const auto b = t.box(m);
    bool in = true;
    for (int i = 0; i < D; ++i) in = in && b.lo[i] <= p[i] && p[i] <= b.hi[i];
    if (in) out.push_back(m);
  }
  return out;
}

}  // namespace pqmesh::test
