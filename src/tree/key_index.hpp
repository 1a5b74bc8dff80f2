#pragma once
// Flat open-addressing hash index from a box key to the first node carrying that key
// (the head of the key's node list; duplicates hang off the head in creation order).
//
// The table stores only (32-bit hash tag, node id); key equality is decided by the
// caller, who owns the keys (in the node array). Linear probing, power-of-two
// capacity, load factor <= 0.7, no deletions (tree keys are never removed). The
// probe sequence depends only on the hash and the insertion order, so the table is
// deterministic; nothing ever iterates over it.
#include <cstdint>
#include <vector>

#include "tree/key.hpp"
#include "geometry/large_page_allocator.hpp"

namespace pqmesh::detail {

class KeyIndex {
 public:
  KeyIndex() { slots_.assign(64, Slot{}); }

  // Node id stored for a key with hash h for which same(id) holds, or -1.
  template <class Same>
  std::int32_t find(KeyHash h, Same&& same) const {
    const std::uint64_t mask = slots_.size() - 1;
    const std::uint32_t tag = h.tag;
    for (std::uint64_t i = h.pos & mask;; i = (i + 1) & mask) {
      const Slot& s = slots_[i];
      if (s.node < 0) return -1;
      if (s.tag == tag && same(s.node)) return s.node;
    }
  }

  // Adds node `id` for a key with hash h that is not yet in the index. `hash_of(id)`
  // recomputes the hash of a stored node's key when the table grows.
  template <class HashOf>
  void insert(KeyHash h, std::int32_t id, HashOf&& hash_of) {
    if ((count_ + 1) * 10 > slots_.size() * 7) grow(hash_of);
    place(h, id);
    ++count_;
  }

  std::size_t size() const { return count_; }

  // Performance hint only: brings the home slot of a key with hash h into cache
  // (a later insert or find of that key then does not wait for memory). The empty
  // volatile asm keeps the hint: GCC 12 otherwise deems the call side-effect free
  // and deletes it together with the hash computed for it.
  void prefetch(KeyHash h) const {
    const Slot* s = &slots_[h.pos & (slots_.size() - 1)];
    __builtin_prefetch(s);
    asm volatile("" : : "r"(s));
  }

  // Grows the table now so that n keys fit without further growth; never shrinks.
  // One reallocation to the final capacity (the doublings in between would each
  // allocate, and the kernel clear, a fresh table).
  template <class HashOf>
  void reserve(std::size_t n, HashOf&& hash_of) {
    std::size_t size = slots_.size();
    while (n * 10 > size * 7) size *= 2;
    if (size > slots_.size()) grow_to(size, hash_of);
  }

 private:
  struct Slot {
    std::uint32_t tag = 0;
    std::int32_t node = -1;
  };

  void place(KeyHash h, std::int32_t id) {
    const std::uint64_t mask = slots_.size() - 1;
    std::uint64_t i = h.pos & mask;
    while (slots_[i].node >= 0) i = (i + 1) & mask;
    slots_[i] = Slot{h.tag, id};
  }

  template <class HashOf>
  void grow(HashOf&& hash_of) {
    grow_to(slots_.size() * 2, hash_of);
  }

  template <class HashOf>
  void grow_to(std::size_t size, HashOf&& hash_of) {
    std::vector<Slot, LargePageAllocator<Slot>> old(size);
    old.swap(slots_);
    // Re-insert in old slot order: deterministic.
    for (const Slot& s : old)
      if (s.node >= 0) place(hash_of(s.node), s.node);
  }

  std::vector<Slot, LargePageAllocator<Slot>> slots_;
  std::size_t count_ = 0;
};

}  // namespace pqmesh::detail
