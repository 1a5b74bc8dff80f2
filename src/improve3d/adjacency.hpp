#pragma once
// Vertex -> elements adjacency of CollapseMesh: one contiguous segment of a
// shared pool per vertex, so a traversal reads the ids in sequence and the
// element records it then loads are independent (the processor overlaps
// them), unlike a linked list whose every step waits for the last.
//
// Invariant: the segment of a live vertex holds every live element of that
// vertex exactly once, plus possibly dead elements, which a traversal drops
// as it meets them (the segment is compacted in place). A segment that must
// grow beyond its capacity moves to the end of the pool with twice the room;
// the hole it leaves is not reused, and the doubling keeps the pool within a
// small multiple of the ids ever appended: when a moved segment does not fit
// the pool's capacity, the segments are packed into a new pool without holes
// with a quarter spare (amortised O(1) per appended id; no doubling).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pqmesh::improve3d::detail {

class Adjacency {
 public:
  // Segments for vertex_count vertices from elements with K vertex ids each
  // (ids listed in increasing element order per vertex).
  template <class Element>
  void build(const std::vector<Element>& elements, std::size_t vertex_count);

  // Appends the elements of v for which alive(e) holds to out and drops the
  // others from v's segment.
  template <class Alive>
  void gather(int v, Alive alive, std::vector<int>& out);

  void append(int v, std::span<const int> elements);
  void clear(int v) { size_[static_cast<std::size_t>(v)] = 0; }

  // Renumbers the elements after their ids were compacted: new_id[e] is e's
  // new id, or -1 when e is dead (dropped). Each segment keeps its order and
  // moves into a new pool without holes, with kSlack spare entries. O(pool).
  void renumber(const std::vector<int>& new_id);

 private:
  // Moves every segment, in vertex order, into a new pool without holes
  // (kSlack spare entries each), leaving max(a quarter, room) free at its end;
  // new_id (may be null: ids kept) as in renumber.
  void rebuild(const int* new_id, std::size_t room);
  void pack(std::size_t room);

  std::vector<int> pool_;
  std::vector<std::int64_t> begin_;
  std::vector<int> size_, capacity_;
};

template <class Element>
void Adjacency::build(const std::vector<Element>& elements, std::size_t vertex_count) {
  begin_.assign(vertex_count + 1, 0);
  for (const Element& e : elements)
    for (const int v : e) ++begin_[static_cast<std::size_t>(v) + 1];
  size_.assign(vertex_count, 0);
  capacity_.resize(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    capacity_[v] = static_cast<int>(begin_[v + 1]);
    begin_[v + 1] += begin_[v];
  }
  pool_.resize(static_cast<std::size_t>(begin_[vertex_count]));
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (const int v : elements[e]) {
      const std::size_t x = static_cast<std::size_t>(v);
      pool_[static_cast<std::size_t>(begin_[x]) + static_cast<std::size_t>(size_[x]++)] = static_cast<int>(e);
    }
  begin_.pop_back();
}

template <class Alive>
void Adjacency::gather(int v, Alive alive, std::vector<int>& out) {
  const std::size_t x = static_cast<std::size_t>(v);
  int* segment = pool_.data() + begin_[x];
  int kept = 0;
  for (int i = 0; i < size_[x]; ++i) {
    const int e = segment[i];
    if (!alive(e)) continue;
    segment[kept++] = e;
    out.push_back(e);
  }
  size_[x] = kept;
}

}  // namespace pqmesh::improve3d::detail
