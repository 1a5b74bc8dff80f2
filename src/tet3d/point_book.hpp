#pragma once
// Mesh vertices by key (vertex_key.hpp): the first request for a key fixes
// its id (order of first use, deterministic) and its coordinates; later
// requests with the same key return the same id whatever coordinates they
// pass, so every box that uses a vertex sees one rounding of it.
// With a warp table (set_warps), a Grid key of a grid point the table moved
// names its moved copy, key (Warped, p, F) and the table's coordinates,
// whichever call site asks (grid_vertex in warp.hpp does the same): a square
// centre carried with its corners (warp.hpp) is one vertex on both sides.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pqmesh/vec.hpp"
#include "tet3d/vertex_key.hpp"
#include "tet3d/warp_table.hpp"

namespace pqmesh::tet3d {

class PointBook {
 public:
  template <class MakeCoordinates>
  int id(const VertexKey& key, MakeCoordinates&& make) {
    if (warps_ != nullptr && key.kind == VertexKind::Grid)
      if (const Warp* w = warps_->find(key.p)) return add({VertexKind::Warped, key.p, {}, w->facet}, [&] { return w->at; });
    return add(key, make);
  }
  // The table grid keys resolve through (may be null: none).
  void set_warps(const WarpTable* warps) { warps_ = warps; }
  int find(const VertexKey& key) const {
    if (slots_.empty()) return -1;
    const std::uint64_t h = mixed_hash(key);
    for (std::size_t i = h & mask_;; i = (i + 1) & mask_) {
      const Slot s = slots_[i];
      if (s.id < 0) return -1;
      if (s.tag == tag_of(h) && keys_[static_cast<std::size_t>(s.id)] == key) return s.id;
    }
  }
  const Vec3& point(int id) const { return points_[static_cast<std::size_t>(id)]; }
  const VertexKey& key(int id) const { return keys_[static_cast<std::size_t>(id)]; }
  int size() const { return static_cast<int>(keys_.size()); }
  const std::vector<Vec3>& points() const { return points_; }

 private:
  // Open addressing with linear probing (issue 5 item 8): a slot holds the
  // id and 32 bits of the key's hash; the key itself is read from keys_ only
  // when the tags agree. 8 B per slot at load <= 1/2 instead of a ~90 B node
  // per vertex in std::unordered_map. Ids are assigned in order of first use
  // whatever the table layout, so the layout never changes the output.
  struct Slot {
    std::uint32_t tag = 0;
    std::int32_t id = -1;  // -1: empty
  };
  static std::uint64_t mixed_hash(const VertexKey& key) {
    // The MurmurHash3 finalizer over VertexKeyHash: every input bit reaches the
    // low bits that pick the slot.
    std::uint64_t x = VertexKeyHash{}(key);
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdull;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ull;
    return x ^ (x >> 33);
  }
  static std::uint32_t tag_of(std::uint64_t h) { return static_cast<std::uint32_t>(h >> 32); }
  void insert_slot(std::uint64_t h, std::int32_t id) {
    std::size_t i = h & mask_;
    while (slots_[i].id >= 0) i = (i + 1) & mask_;
    slots_[i] = {tag_of(h), id};
  }
  void grow() {
    const std::size_t capacity = slots_.empty() ? 1024 : 2 * slots_.size();
    slots_.assign(capacity, Slot{});
    mask_ = capacity - 1;
    for (std::size_t id = 0; id < keys_.size(); ++id) insert_slot(mixed_hash(keys_[id]), static_cast<std::int32_t>(id));
  }

  template <class MakeCoordinates>
  int add(const VertexKey& key, MakeCoordinates&& make) {
    if (2 * (keys_.size() + 1) > slots_.size()) grow();  // keeps load <= 1/2
    const std::uint64_t h = mixed_hash(key);
    std::size_t i = h & mask_;
    for (;; i = (i + 1) & mask_) {
      const Slot s = slots_[i];
      if (s.id < 0) break;
      if (s.tag == tag_of(h) && keys_[static_cast<std::size_t>(s.id)] == key) return s.id;
    }
    const int n = static_cast<int>(keys_.size());
    slots_[i] = {tag_of(h), n};
    keys_.push_back(key);
    points_.push_back(make());
    return n;
  }

  const WarpTable* warps_ = nullptr;
  std::vector<Slot> slots_;  // size 0 or a power of two
  std::size_t mask_ = 0;
  std::vector<VertexKey> keys_;
  std::vector<Vec3> points_;
};

}  // namespace pqmesh::tet3d
