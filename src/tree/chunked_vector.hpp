#pragma once
// Append-only array stored in fixed-size chunks: growing never copies or moves the
// elements (references stay valid) and never touches memory twice, which matters for
// trees of millions of nodes (a doubling std::vector copies and re-faults ~2x the
// final size). Indexing is one shift and one mask.
//
// Where the chunks live. By default each chunk is its own malloc block. With
// kHugeSlabs, only the first kSmallChunks chunks are (a small array stays a small
// allocation); after them, chunks are carved in order from slabs: blocks of a whole
// number of 2 MiB pages, 2 MiB-aligned and, on Linux, marked MADV_HUGEPAGE, as
// geometry/large_page_allocator.hpp does. With transparent huge pages in "madvise"
// mode the kernel then backs a slab by 2 MiB pages as it is filled (one page fault
// per 2 MiB instead of 512) and the slabs go back to the system as a whole when the
// array is freed. A slab holds a whole number of chunks and is a whole number of
// 2 MiB pages, so no huge page holds other data and only the last one touched can
// be partly unused. Only where memory comes from changes: contents and indexing
// are the same either way.
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <numeric>
#include <type_traits>
#include <vector>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pqmesh::detail {

template <class T, int kChunkBits = 13, bool kHugeSlabs = false>
class ChunkedVector {
  // Elements are copied in and never destroyed one by one.
  static_assert(std::is_trivially_destructible_v<T> && std::is_trivially_copyable_v<T>);
  static_assert(alignof(T) <= alignof(std::max_align_t));  // malloc's alignment suffices

 public:
  static constexpr std::size_t kChunk = std::size_t{1} << kChunkBits;

  ChunkedVector() = default;
  ChunkedVector(const ChunkedVector&) = delete;
  ChunkedVector& operator=(const ChunkedVector&) = delete;
  ChunkedVector(ChunkedVector&&) noexcept = default;
  ChunkedVector& operator=(ChunkedVector&&) noexcept = default;

  std::size_t size() const { return size_; }
  const T& operator[](std::size_t i) const { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
  T& operator[](std::size_t i) { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }

  void push_back(const T& v) {
    if ((size_ & (kChunk - 1)) == 0) add_chunk();
    ::new (static_cast<void*>(chunks_.back() + (size_ & (kChunk - 1)))) T(v);
    ++size_;
  }

  void reserve(std::size_t n) { chunks_.reserve((n + kChunk - 1) / kChunk); }

 private:
  static constexpr std::size_t kChunkBytes = kChunk * sizeof(T);
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;
  // Chunks per slab: the fewest that fill whole 2 MiB pages, times the fewest
  // that make a slab of at least 8 MiB (fewer slabs; the unused tail of the last
  // slab is never touched, so it costs address space only).
  static constexpr std::size_t kSlabUnit = kHugePage / std::gcd(kChunkBytes, kHugePage);
  static constexpr std::size_t kSlabChunks =
      kSlabUnit * ((((std::size_t{8} << 20) + kSlabUnit * kChunkBytes - 1) / (kSlabUnit * kChunkBytes)));
  static constexpr std::size_t kSlabBytes = kSlabChunks * kChunkBytes;
  static_assert(kSlabBytes % kHugePage == 0);
  // Chunks allocated one by one before the first slab: under 2 MiB in all.
  static constexpr std::size_t kSmallChunks = kHugePage / kChunkBytes;

  struct Free {
    void operator()(void* p) const { std::free(p); }
  };
  using Block = std::unique_ptr<void, Free>;

  static Block allocate(std::size_t bytes, bool huge) {
    void* p = huge ? std::aligned_alloc(kHugePage, bytes) : std::malloc(bytes);  // huge: bytes % kHugePage == 0
    if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge) madvise(p, bytes, MADV_HUGEPAGE);  // a hint: failure only costs speed
#endif
    return Block(p);
  }

  void add_chunk() {
    const std::size_t c = chunks_.size();
    if (!kHugeSlabs || c < kSmallChunks) {
      blocks_.push_back(allocate(kChunkBytes, false));
      chunks_.push_back(static_cast<T*>(blocks_.back().get()));
      return;
    }
    const std::size_t in_slab = (c - kSmallChunks) % kSlabChunks;
    if (in_slab == 0) blocks_.push_back(allocate(kSlabBytes, true));
    chunks_.push_back(static_cast<T*>(blocks_.back().get()) + in_slab * kChunk);
  }

  std::vector<T*> chunks_;
  std::vector<Block> blocks_;  // the small chunks, then the slabs, in order
  std::size_t size_ = 0;
};

}  // namespace pqmesh::detail
