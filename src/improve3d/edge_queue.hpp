#pragma once
// The order of the collapses: edges by length, shortest first, ties by
// (smaller id, larger id), so the output does not depend on anything but the
// input (docs/DESIGN_RULES.md "Determinism").
//
// A pass starts from a list of edges, sorted once; edges created by
// collapses go to a heap; pop() takes the smaller of the two heads. Vertices
// never move, so an entry's key stays exact; an entry is stale when an end
// has been deleted, which the caller checks.
//
// Memory: the list and the heap are deques (blocks of a few hundred bytes).
// A pass of millions of edges frees the list's blocks as it pops them, the
// heap grows and shrinks by blocks (no doubling, no copy), and the caller's
// records of refused edges (also a deque) reuse the freed blocks.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <queue>
#include <vector>

namespace pqmesh::improve3d::detail {

struct EdgeEntry {
  double length2 = 0;  // squared length (a construction; equal doubles tie by ids)
  int a = -1, b = -1;  // a < b
};

// Strict order of the entries: (length2, a, b); equal keys are copies of one
// edge (tried again, harmlessly).
inline bool earlier(const EdgeEntry& x, const EdgeEntry& y) {
  if (x.length2 != y.length2) return x.length2 < y.length2;
  if (x.a != y.a) return x.a < y.a;
  return x.b < y.b;
}

using EdgeList = std::deque<EdgeEntry>;

class EdgeQueue {
 public:
  // The sorted start of a pass.
  void start(EdgeList entries);
  void push(const EdgeEntry& e) { heap_.push(e); }
  bool empty() const { return sorted_.empty() && heap_.empty(); }
  EdgeEntry pop();
  // Frees the entries (the queue must be empty or is emptied).
  void release() {
    sorted_ = {};
    heap_ = {};
  }

 private:
  struct Later {
    bool operator()(const EdgeEntry& x, const EdgeEntry& y) const { return earlier(y, x); }
  };
  EdgeList sorted_;  // the rest of the sorted start, front first
  std::priority_queue<EdgeEntry, std::deque<EdgeEntry>, Later> heap_;
};

}  // namespace pqmesh::improve3d::detail
