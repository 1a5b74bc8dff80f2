#include "improve3d/adjacency.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace pqmesh::improve3d::detail {

std::vector<int> Adjacency::by_place() const {
  std::vector<int> order(size_.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    const std::int64_t bx = begin_[static_cast<std::size_t>(x)], by = begin_[static_cast<std::size_t>(y)];
    return bx != by ? bx < by : x < y;
  });
  return order;
}

void Adjacency::spread(const std::vector<int>& order, std::size_t end, std::size_t room) {
  std::size_t total = end;
  for (const int s : size_)
    if (s > 0) total += kSlack;
  std::vector<int> grown;
  if (pool_.capacity() < total + std::max(total / 8, room)) grown.reserve(total + std::max(total / 4, room));
  std::vector<int>& to = grown.capacity() > 0 ? grown : pool_;
  to.resize(std::max(to.size(), total));
  // From the last segment back: a segment moves up, past no segment not yet
  // moved (in place), or into the new pool.
  std::size_t top = total;
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const std::size_t x = static_cast<std::size_t>(*it);
    const int size = size_[x];
    capacity_[x] = size > 0 ? size + kSlack : 0;
    top -= static_cast<std::size_t>(capacity_[x]);
    const auto from = pool_.begin() + begin_[x];
    std::copy_backward(from, from + size, to.begin() + static_cast<std::ptrdiff_t>(top) + size);
    begin_[x] = static_cast<std::int64_t>(top);
  }
  if (grown.capacity() > 0) pool_ = std::move(grown);
  pool_.resize(total);
}

}  // namespace pqmesh::improve3d::detail
