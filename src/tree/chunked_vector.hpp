#pragma once
// Append-only array stored in fixed-size chunks: growing never copies or moves the
// elements (references stay valid) and never touches memory twice, which matters for
// trees of millions of nodes (a doubling std::vector copies and re-faults ~2x the
// final size). Indexing is one shift and one mask.
#include <cstddef>
#include <vector>

namespace pqmesh::detail {

template <class T, int kChunkBits = 13>
class ChunkedVector {
 public:
  static constexpr std::size_t kChunk = std::size_t{1} << kChunkBits;

  std::size_t size() const { return size_; }
  const T& operator[](std::size_t i) const { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
  T& operator[](std::size_t i) { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }

  void push_back(const T& v) {
    if ((size_ & (kChunk - 1)) == 0) {
      chunks_.emplace_back();
      chunks_.back().reserve(kChunk);
    }
    chunks_.back().push_back(v);  // within capacity: no reallocation
    ++size_;
  }

  void reserve(std::size_t n) { chunks_.reserve((n + kChunk - 1) / kChunk); }

 private:
  std::vector<std::vector<T>> chunks_;
  std::size_t size_ = 0;
};

}  // namespace pqmesh::detail
