#include "improve3d/adjacency.hpp"

#include <algorithm>

namespace pqmesh::improve3d::detail {

void Adjacency::append(int v, std::span<const int> elements) {
  const std::size_t x = static_cast<std::size_t>(v);
  const int needed = size_[x] + static_cast<int>(elements.size());
  if (needed > capacity_[x]) {
    const std::int64_t moved_to = static_cast<std::int64_t>(pool_.size());
    pool_.resize(pool_.size() + 2 * static_cast<std::size_t>(needed));
    std::copy_n(pool_.begin() + begin_[x], size_[x], pool_.begin() + moved_to);
    begin_[x] = moved_to;
    capacity_[x] = 2 * needed;
  }
  std::copy(elements.begin(), elements.end(), pool_.begin() + begin_[x] + size_[x]);
  size_[x] = needed;
}

}  // namespace pqmesh::improve3d::detail
