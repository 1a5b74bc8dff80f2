#pragma once
// What the shape memos (triangle_quality_memo, tetrahedron_quality_memo)
// share: the exactness test of a coordinate difference, which makes a shape
// key sound, and the slot of a key in a direct-mapped table.
#include <cstddef>
#include <cstdint>

namespace pqmesh::detail {

// x - y is exact: Knuth's two-difference leaves no rounding error. (NaN or
// infinite inputs give a non-zero or NaN error: not exact.)
inline bool exact_difference(double x, double y) {
  const double d = x - y;
  const double y_virtual = x - d, x_virtual = d + y_virtual;
  const double error = (x - x_virtual) + (y_virtual - y);
  return error == 0;
}

// The slot of `key` in a table of 2^bits entries: the top bits of a
// multiply-xorshift mix of its words.
template <std::size_t N>
std::size_t memo_slot(const std::uint64_t (&key)[N], int bits) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (const std::uint64_t k : key) {
    h ^= k;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
  }
  return static_cast<std::size_t>(h >> (64 - bits));
}

}  // namespace pqmesh::detail
