#include "improve3d/edge_queue.hpp"

#include <algorithm>
#include <utility>

namespace pqmesh::improve3d::detail {

void EdgeQueue::start(std::vector<EdgeEntry> entries) {
  sorted_ = std::move(entries);
  std::sort(sorted_.begin(), sorted_.end(), [](const EdgeEntry& x, const EdgeEntry& y) { return earlier(x, y); });
  next_ = 0;
  heap_ = {};
}

EdgeEntry EdgeQueue::pop() {
  const bool from_sorted = next_ < sorted_.size() && (heap_.empty() || !earlier(heap_.top(), sorted_[next_]));
  if (from_sorted) return sorted_[next_++];
  EdgeEntry e = heap_.top();
  heap_.pop();
  return e;
}

}  // namespace pqmesh::improve3d::detail
