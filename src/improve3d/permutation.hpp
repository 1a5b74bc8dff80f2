#pragma once
// Even permutations of a tetrahedron's vertices: an even permutation of a
// positively oriented tetrahedron is positively oriented too, so the flips
// (flips.hpp) and the edge rings (edge_ring.hpp) can name a tetrahedron's
// vertices in the order they need without an orientation test.
#include <array>
#include <cstddef>
#include <utility>

namespace pqmesh::improve3d::detail {

inline bool odd_permutation(const std::array<int, 4>& p) {
  int inversions = 0;
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = a + 1; b < 4; ++b) inversions += p[a] > p[b];
  return (inversions & 1) != 0;
}

inline std::array<int, 4> permuted(const std::array<int, 4>& k, const std::array<int, 4>& p) {
  return {k[static_cast<std::size_t>(p[0])], k[static_cast<std::size_t>(p[1])], k[static_cast<std::size_t>(p[2])],
          k[static_cast<std::size_t>(p[3])]};
}

// The vertices of k as an even permutation with k[i] first and k[j] second (i != j).
inline std::array<int, 4> starting_with(const std::array<int, 4>& k, int i, int j) {
  std::array<int, 4> p{i, j, -1, -1};
  std::size_t n = 2;
  for (int x = 0; x < 4; ++x)
    if (x != i && x != j) p[n++] = x;
  if (odd_permutation(p)) std::swap(p[2], p[3]);
  return permuted(k, p);
}

// The vertices of k as an even permutation with k[i] last.
inline std::array<int, 4> ending_with(const std::array<int, 4>& k, int i) {
  std::array<int, 4> p{-1, -1, -1, i};
  std::size_t n = 0;
  for (int x = 0; x < 4; ++x)
    if (x != i) p[n++] = x;
  if (odd_permutation(p)) std::swap(p[0], p[1]);
  return permuted(k, p);
}

}  // namespace pqmesh::improve3d::detail
