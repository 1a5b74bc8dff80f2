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
// the hole it leaves is not reused until the pool is full: then the segments
// are packed in place, in pool order, without holes and without dead
// elements, each non-empty one with kSlack spare entries. The pool grows (a new buffer with
// a quarter spare) only when packing leaves less than an eighth free, so a
// pack never holds two pools while the elements' count does not grow
// (amortised O(1) per appended id; no doubling).
#include <algorithm>
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

  // Appends elements to v's segment; alive(e) tells the dead elements a pack drops.
  template <class Alive>
  void append(int v, std::span<const int> elements, Alive alive);
  void clear(int v) { size_[static_cast<std::size_t>(v)] = 0; }

  // Renumbers the elements after their ids were compacted: new_id[e] is e's
  // new id, or -1 when e is dead (dropped). Each segment keeps its order.
  // O(pool + vertices log vertices).
  void renumber(const std::vector<int>& new_id) {
    rebuild([&](int e) { return new_id[static_cast<std::size_t>(e)]; }, 0);
  }

  std::size_t pool_capacity() const { return pool_.capacity(); }

 private:
  static constexpr int kSlack = 2;

  // Packs the segments (see above) with map(e) for each element e: its id
  // after the pack, or -1 to drop it; leaves at least room free at the end.
  template <class Map>
  void rebuild(Map map, std::size_t room);
  // The vertices by the place of their segment in the pool (ties by vertex).
  std::vector<int> by_place() const;
  // After the elements are moved down to pool_[0 .. end), in the order of
  // `order`: spreads them with kSlack after each non-empty segment, in place
  // or into a new pool when less than an eighth (or room) would be free.
  void spread(const std::vector<int>& order, std::size_t end, std::size_t room);

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
  const auto ids = static_cast<std::size_t>(begin_[vertex_count]);
  pool_.reserve(ids + ids / 8);
  pool_.resize(ids);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (const int v : elements[e]) {
      const std::size_t x = static_cast<std::size_t>(v);
      pool_[static_cast<std::size_t>(begin_[x]) + static_cast<std::size_t>(size_[x]++)] = static_cast<int>(e);
    }
  begin_.pop_back();
}

template <class Alive>
void Adjacency::append(int v, std::span<const int> elements, Alive alive) {
  const std::size_t x = static_cast<std::size_t>(v);
  const int needed = size_[x] + static_cast<int>(elements.size());
  if (needed > capacity_[x]) {
    const std::size_t room = 2 * static_cast<std::size_t>(needed);
    if (pool_.size() + room > pool_.capacity()) rebuild([&](int e) { return alive(e) ? e : -1; }, room);
    const int size = size_[x];  // the pack may drop dead elements of v
    const std::int64_t moved_to = static_cast<std::int64_t>(pool_.size());
    pool_.resize(pool_.size() + room);
    std::copy_n(pool_.begin() + begin_[x], size, pool_.begin() + moved_to);
    begin_[x] = moved_to;
    capacity_[x] = static_cast<int>(room);
  }
  std::copy(elements.begin(), elements.end(), pool_.begin() + begin_[x] + size_[x]);
  size_[x] += static_cast<int>(elements.size());
}

template <class Map>
void Adjacency::rebuild(Map map, std::size_t room) {
  // Segments in pool order: moving each down to the running end never
  // overwrites a segment not yet moved (their ranges are disjoint and a
  // segment only shrinks).
  const std::vector<int> order = by_place();
  std::size_t end = 0;
  for (const int v : order) {
    const std::size_t x = static_cast<std::size_t>(v);
    const std::size_t from = static_cast<std::size_t>(begin_[x]), begin = end;
    for (std::size_t i = 0; i < static_cast<std::size_t>(size_[x]); ++i) {
      const int e = map(pool_[from + i]);
      if (e >= 0) pool_[end++] = e;
    }
    begin_[x] = static_cast<std::int64_t>(begin);
    size_[x] = static_cast<int>(end - begin);
  }
  spread(order, end, room);
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
