#pragma once
// Stable least-significant-digit radix sort by 64-bit unsigned keys, and
// order-preserving integer keys of doubles, for the checker's large sorts. A
// pure sorting utility with no mesh knowledge (the mesher does not use it:
// checker and mesher share no face code).
//
// Why: the checker sorts hundreds of thousands of small records (faces,
// edges, facet records) by integer tuples. A comparison sort
// costs ~n log n comparator calls; this costs one read pass (eight digit
// histograms at once) plus one scatter pass per 8-bit digit that is not the
// same for every item (ids below 2^24 need at most three per 32-bit field).
//
// Stability is the contract: items with equal keys keep their input order.
// A lexicographic order on several fields is obtained by sorting on the least
// significant field first, then on each more significant one (each pass keeps
// the order the previous passes made among equal keys); ties on all fields end
// in input order, which callers use as their documented tie-break.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pqmesh::detail {

// Sorts items stably by key(item) (an std::uint64_t), ascending. scratch is a
// buffer the caller may reuse between calls (resized here; contents unspecified
// afterwards). key is evaluated once per item for the histograms and twice per
// item per scatter pass, so it should be cheap (a field or a shift).
// (Measured on plate_holes: 8-bit digits with constant-digit skipping cost
// fewer instructions than 11-bit digits of the key range after a min/max
// pass, in every caller.)
template <class T, class Key>
void radix_sort_by_key(std::vector<T>& items, std::vector<T>& scratch, Key key) {
  const std::size_t n = items.size();
  if (n < 2) return;
  std::array<std::array<std::size_t, 256>, 8> count{};
  for (const T& x : items) {
    const std::uint64_t k = key(x);
    for (int d = 0; d < 8; ++d) ++count[static_cast<std::size_t>(d)][(k >> (8 * d)) & 0xffu];
  }
  scratch.resize(n);
  const std::uint64_t first_key = key(items.front());
  for (int d = 0; d < 8; ++d) {
    auto& c = count[static_cast<std::size_t>(d)];
    // A digit every item shares leaves the order unchanged: skip its pass.
    if (c[(first_key >> (8 * d)) & 0xffu] == n) continue;
    std::size_t sum = 0;
    for (auto& slot : c) {  // counts -> first output position of each digit
      const std::size_t here = slot;
      slot = sum;
      sum += here;
    }
    for (const T& x : items) scratch[c[(key(x) >> (8 * d)) & 0xffu]++] = x;
    items.swap(scratch);
  }
}

// Convenience overload with a local scratch buffer.
template <class T, class Key>
void radix_sort_by_key(std::vector<T>& items, Key key) {
  std::vector<T> scratch;
  radix_sort_by_key(items, scratch, key);
}

// An unsigned key with the order of the double x (x finite or infinite, not
// NaN): key(x) < key(y) iff x < y, and key(-0.0) == key(+0.0) as -0.0 == +0.0.
// Positive doubles order like their bit patterns; negative ones in reverse, so
// those are complemented and the sign bit of the others is set.
inline std::uint64_t ordered_key(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x == 0.0 ? 0.0 : x);
  return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

}  // namespace pqmesh::detail
