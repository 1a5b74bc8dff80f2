// detail::ChunkedVector: the same elements at the same indices whether chunks are
// malloc blocks or carved from huge-page slabs, and elements never move.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tree/chunked_vector.hpp"

namespace pqmesh {
namespace {

std::uint32_t value_of(std::size_t i) { return static_cast<std::uint32_t>(i * 2654435761u + 12345u); }

// 16 elements of 4 bytes per chunk: with slabs, the first 32768 chunks (2 MiB)
// are malloc blocks and the slabs are 8 MiB (131072 chunks), so 5 million
// elements cross from the small chunks into slabs and fill two slabs and part
// of a third.
template <bool kHugeSlabs>
void check_chunked_vector() {
  constexpr std::size_t n = 5'000'000;
  detail::ChunkedVector<std::uint32_t, 4, kHugeSlabs> v;
  std::vector<const std::uint32_t*> address;  // where each sampled element was put
  const std::vector<std::size_t> sampled = {0, 15, 16, 524'287, 524'288, 2'621'439, 2'621'440, 4'718'591, 4'718'592,
                                            n - 1};
  for (std::size_t i = 0; i < n; ++i) {
    v.push_back(value_of(i));
    for (const std::size_t s : sampled)
      if (s == i) address.push_back(&v[i]);
  }
  ASSERT_EQ(v.size(), n);
  for (std::size_t i = 0; i < n; ++i)
    if (v[i] != value_of(i)) FAIL() << "element " << i << " is " << v[i] << ", expected " << value_of(i);
  for (std::size_t k = 0; k < sampled.size(); ++k) EXPECT_EQ(address[k], &v[sampled[k]]) << "element " << sampled[k] << " moved";
  // Within a chunk the elements are contiguous.
  for (const std::size_t s : sampled) {
    if (s % 16 != 15) {
      EXPECT_EQ(&v[s] + 1, &v[s + 1]) << "element " << s;
    }
  }
  v[n / 2] = 7;  // writable through operator[]
  EXPECT_EQ(v[n / 2], 7u);
}

TEST(TreeChunkedVector, MallocChunksKeepElementsInPlace) { check_chunked_vector<false>(); }

TEST(TreeChunkedVector, HugePageSlabsKeepElementsInPlace) { check_chunked_vector<true>(); }

}  // namespace
}  // namespace pqmesh
