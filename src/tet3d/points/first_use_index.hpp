#pragma once
// A set of keys numbered in order of first insertion (ids 0, 1, 2, ...), with
// lookup by key: the index behind PointBook (point_book.hpp) and CornerSet
// (box_faces.hpp). Ids follow insertion order, never the hash, so the
// output does not depend on the layout.
//
// Layout: open addressing with linear probing. A slot holds an id and 32 bits
// of the key's hash; the key itself lives in keys_ (by id) and is read only
// when the tags agree, so a miss usually ends in the 8-byte slot array. The
// load stays <= 1/2: 16 to 32 B of slots per key, instead of a ~60 to 90 B
// heap node (and one malloc) per key in std::unordered_map.
//
// Invariant: ids depend only on the order of the insert calls, never on the
// hash or the table size, so the layout cannot change any output that is
// ordered by id.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pqmesh::tet3d {

template <class Key, class Hash>
class FirstUseIndex {
 public:
  // The id of `key` and whether this call gave it (true: `key` was new).
  std::pair<int, bool> insert(const Key& key) {
    if (2 * (keys_.size() + 1) > slots_.size()) grow();  // keeps load <= 1/2
    const std::uint64_t h = mixed_hash(key);
    std::size_t i = h & mask_;
    for (;; i = (i + 1) & mask_) {
      const Slot s = slots_[i];
      if (s.id < 0) break;
      if (s.tag == tag_of(h) && keys_[static_cast<std::size_t>(s.id)] == key) return {s.id, false};
    }
    const int n = static_cast<int>(keys_.size());
    slots_[i] = {tag_of(h), n};
    keys_.push_back(key);
    return {n, true};
  }
  // The id of `key`, or -1 if it was never inserted.
  int find(const Key& key) const {
    if (slots_.empty()) return -1;
    const std::uint64_t h = mixed_hash(key);
    for (std::size_t i = h & mask_;; i = (i + 1) & mask_) {
      const Slot s = slots_[i];
      if (s.id < 0) return -1;
      if (s.tag == tag_of(h) && keys_[static_cast<std::size_t>(s.id)] == key) return s.id;
    }
  }
  const Key& key(int id) const { return keys_[static_cast<std::size_t>(id)]; }
  int size() const { return static_cast<int>(keys_.size()); }
  // The keys by id, moved out (no copy at the peak of a run); the index is
  // empty afterwards.
  std::vector<Key> take_keys() {
    std::vector<Slot>().swap(slots_);
    mask_ = 0;
    std::vector<Key> out = std::move(keys_);
    keys_.clear();
    return out;
  }

 private:
  struct Slot {
    std::uint32_t tag = 0;
    std::int32_t id = -1;  // -1: empty
  };
  static std::uint64_t mixed_hash(const Key& key) {
    // The MurmurHash3 finalizer over Hash: every input bit reaches the low
    // bits that pick the slot (grid coordinates are multiples of large powers
    // of two, so their own low bits are all zero).
    std::uint64_t x = static_cast<std::uint64_t>(Hash{}(key));
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdull;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ull;
    return x ^ (x >> 33);
  }
  static std::uint32_t tag_of(std::uint64_t h) { return static_cast<std::uint32_t>(h >> 32); }
  void grow() {
    const std::size_t capacity = slots_.empty() ? 1024 : 2 * slots_.size();
    slots_.assign(capacity, Slot{});
    mask_ = capacity - 1;
    for (std::size_t id = 0; id < keys_.size(); ++id) {
      const std::uint64_t h = mixed_hash(keys_[id]);
      std::size_t i = h & mask_;
      while (slots_[i].id >= 0) i = (i + 1) & mask_;
      slots_[i] = {tag_of(h), static_cast<std::int32_t>(id)};
    }
  }

  std::vector<Slot> slots_;  // size 0 or a power of two
  std::size_t mask_ = 0;
  std::vector<Key> keys_;    // by id
};

}  // namespace pqmesh::tet3d
