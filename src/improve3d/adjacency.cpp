#include "improve3d/adjacency.hpp"

#include <algorithm>
#include <utility>

namespace pqmesh::improve3d::detail {

void Adjacency::append(int v, std::span<const int> elements) {
  const std::size_t x = static_cast<std::size_t>(v);
  const int needed = size_[x] + static_cast<int>(elements.size());
  if (needed > capacity_[x]) {
    if (pool_.size() + 2 * static_cast<std::size_t>(needed) > pool_.capacity()) pack(2 * static_cast<std::size_t>(needed));
    const std::int64_t moved_to = static_cast<std::int64_t>(pool_.size());
    pool_.resize(pool_.size() + 2 * static_cast<std::size_t>(needed));
    std::copy_n(pool_.begin() + begin_[x], size_[x], pool_.begin() + moved_to);
    begin_[x] = moved_to;
    capacity_[x] = 2 * needed;
  }
  std::copy(elements.begin(), elements.end(), pool_.begin() + begin_[x] + size_[x]);
  size_[x] = needed;
}

void Adjacency::renumber(const std::vector<int>& new_id) { rebuild(new_id.data(), 0); }

void Adjacency::pack(std::size_t room) { rebuild(nullptr, room); }

void Adjacency::rebuild(const int* new_id, std::size_t room) {
  constexpr int kSlack = 2;
  std::size_t total = 0;
  for (std::size_t x = 0; x < size_.size(); ++x) total += static_cast<std::size_t>(size_[x]) + kSlack;
  std::vector<int> pool;
  pool.reserve(total + std::max(total / 4, room));
  for (std::size_t x = 0; x < size_.size(); ++x) {
    const std::int64_t begin = static_cast<std::int64_t>(pool.size());
    const int* segment = pool_.data() + begin_[x];
    for (int i = 0; i < size_[x]; ++i) {
      const int e = new_id == nullptr ? segment[i] : new_id[static_cast<std::size_t>(segment[i])];
      if (e >= 0) pool.push_back(e);
    }
    begin_[x] = begin;
    size_[x] = static_cast<int>(static_cast<std::int64_t>(pool.size()) - begin);
    capacity_[x] = size_[x] + kSlack;
    pool.resize(pool.size() + kSlack);
  }
  pool_ = std::move(pool);
}

}  // namespace pqmesh::improve3d::detail
