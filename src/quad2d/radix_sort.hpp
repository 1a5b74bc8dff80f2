#pragma once
// Stable least-significant-digit radix sort on an unsigned integer key of at
// most `bits` bits (the mesher's large sorts: leaf corners, z-order). Linear
// in the input, ceil(bits / 12) passes of equal digit width (at most 12 bits,
// so the counters stay in cache); a pass whose digit is the same for every
// element is skipped. Stable, so equal keys keep their input order: sorting
// by a key and then by a second key orders by (second, first), and the
// result never depends on anything but the input sequence (deterministic).
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
  std::vector<std::size_t> start(kBuckets);
  for (int shift = 0; shift < bits; shift += kDigit) {
    std::fill(start.begin(), start.end(), 0);
    for (const T& x : v) ++start[static_cast<std::size_t>((key(x) >> shift) & (kBuckets - 1))];
    bool one_bucket = false;
    for (const std::size_t c : start)
      if (c == v.size()) one_bucket = true;
    if (one_bucket) continue;
    std::size_t sum = 0;
    for (std::size_t& s : start) {
      const std::size_t c = s;
      s = sum;
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
