#pragma once
// Stable least-significant-digit radix sort on an unsigned integer key of at
// most `bits` bits (the mesher's large sorts: leaf corners, z-order). Linear
// in the input, ceil(bits / 12) passes of equal digit width (at most 12 bits,
// so the counters stay in cache), all counted in one read of the input; a
// pass whose digit is the same for every element is skipped. Stable, so
// equal keys keep their input order: sorting by a key and then by a second
// key orders by (second, first), and the result never depends on anything
// but the input sequence (deterministic).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pqmesh::quad2d {

// key(element) returns a std::uint64_t below 2^bits (bits <= 64). `scratch`
// is a buffer of the element type, reused between calls to save allocations.
template <class T, class KeyFn>
void radix_sort(std::vector<T>& v, int bits, KeyFn key, std::vector<T>& scratch) {
  if (v.size() < 2 || bits <= 0) return;
  // Digits of at most 12 bits, as few passes as that allows, equal widths.
  const int passes = (bits + 11) / 12;
  const int kDigit = (bits + passes - 1) / passes;
  const std::size_t kBuckets = std::size_t{1} << kDigit;
  scratch.resize(v.size());
  // Every pass's digit counts from one read of the input (a pass does not
  // change the multiset of keys, so its counts are known in advance).
  std::vector<std::size_t> counts(static_cast<std::size_t>(passes) * kBuckets, 0);
  for (const T& x : v) {
    const std::uint64_t k = key(x);
    for (int p = 0; p < passes; ++p)
      ++counts[static_cast<std::size_t>(p) * kBuckets + static_cast<std::size_t>((k >> (p * kDigit)) & (kBuckets - 1))];
  }
  for (int p = 0; p < passes; ++p) {
    const int shift = p * kDigit;
    std::size_t* start = counts.data() + static_cast<std::size_t>(p) * kBuckets;
    bool one_bucket = false;
    for (std::size_t b = 0; b < kBuckets; ++b)
      if (start[b] == v.size()) one_bucket = true;
    if (one_bucket) continue;
    std::size_t sum = 0;
    for (std::size_t b = 0; b < kBuckets; ++b) {
      const std::size_t c = start[b];
      start[b] = sum;
      sum += c;
    }
    for (const T& x : v) scratch[start[static_cast<std::size_t>((key(x) >> shift) & (kBuckets - 1))]++] = x;
    v.swap(scratch);
  }
}

// Number of bits needed for the value m (0 for 0).
inline int bit_width64(std::uint64_t m) {
  int b = 0;
  while (m != 0) {
    ++b;
    m >>= 1;
  }
  return b;
}

}  // namespace pqmesh::quad2d
