#include "improve3d/edge_queue.hpp"

#include <algorithm>
#include <utility>

namespace pqmesh::improve3d::detail {

void EdgeQueue::start(EdgeList entries) {
  sorted_ = std::move(entries);
  std::sort(sorted_.begin(), sorted_.end(), [](const EdgeEntry& x, const EdgeEntry& y) { return earlier(x, y); });
  heap_ = {};
}

EdgeEntry EdgeQueue::pop() {
  if (!sorted_.empty() && (heap_.empty() || !earlier(heap_.top(), sorted_.front()))) {
    const EdgeEntry e = sorted_.front();
    sorted_.pop_front();
    return e;
  }
  EdgeEntry e = heap_.top();
  heap_.pop();
  return e;
}

}  // namespace pqmesh::improve3d::detail
