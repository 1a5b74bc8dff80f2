#pragma once
// Integer keys of quadtree/octree boxes (docs/ARCHITECTURE.md "Modules and
// dependencies", docs/DESIGN_RULES.md "Exact decisions": "tree boxes live on an
// integer grid").
//
// Sizes. The root cube has side h(0) = S; a box of level L has side h(L) = S / 2^L.
//
// Origins. A key stores the box origin in units of HALF its side, h(L+1):
//   origin_a = root_origin_a + q_a * h(L+1),   0 <= q_a < 2^(L+1).
// A box produced by splitting (a "tree-aligned" box) has every q_a even: it is the
// cell q/2 of the level-L grid. The vertex-centering step (thesis §4.1.3, Fig. 4.3)
// unites a 2x2(x2) block of level-(L+1) leaves starting at ANY level-(L+1) cell, so
// the united box has side h(L) but an origin on the finer h(L+1) grid: some q_a may
// be odd. Storing origins in half-side units gives both kinds one key format, and
// every box covers exactly the level-(L+1) cells [q_a, q_a + 2) along each axis.
//
// "Fine units": to compare boxes of different levels we scale everything to the
// grid h(kTreeMaxLevel + 1): lo_a = q_a << (kTreeMaxLevel - L), side 2 << (...).
// With kTreeMaxLevel = 50 all such numbers stay below 2^52.
#include <array>
#include <cstdint>

namespace pqmesh {

inline constexpr int kTreeMaxLevel = 50;

template <int D>
struct BoxKey {
  static_assert(D == 2 || D == 3, "quadtree (2) or octree (3)");
  std::int32_t level = 0;
  std::array<std::int64_t, D> q{};  // origin in units of h(level + 1)

  friend bool operator==(const BoxKey&, const BoxKey&) = default;

  // The tree-aligned box that is cell c of the level-`lev` grid.
  static BoxKey cell(std::int32_t lev, const std::array<std::int64_t, D>& c) {
    BoxKey k;
    k.level = lev;
    for (int a = 0; a < D; ++a) k.q[a] = 2 * c[a];
    return k;
  }

  // True for boxes produced by splitting (origin on the box's own grid).
  bool aligned() const {
    for (int a = 0; a < D; ++a)
      if (q[a] & 1) return false;
    return true;
  }

  // Child `k` (0 <= k < 2^D) of an aligned key: bit a of k selects the upper half
  // along axis a, so child index order is the z-order of the children.
  BoxKey child(int k) const {
    BoxKey c;
    c.level = level + 1;
    for (int a = 0; a < D; ++a) c.q[a] = 2 * q[a] + (((k >> a) & 1) ? 2 : 0);
    return c;
  }

  // Origin along axis a in fine units (see the header comment).
  std::int64_t fine_lo(int a) const { return q[a] << (kTreeMaxLevel - level); }
  // Side in fine units.
  std::int64_t fine_side() const { return std::int64_t{2} << (kTreeMaxLevel - level); }
};

namespace detail {

// Hash of a key for the flat index (key_index.hpp). `pos` picks the home slot: the
// eight (four) children of one cell share the mixed part and differ by their child
// index, so siblings land in neighbouring slots and a neighbour query touches few
// cache lines. `tag` is a 32-bit filter that also separates siblings. Deterministic.
struct KeyHash {
  std::uint64_t pos = 0;
  std::uint32_t tag = 0;
};

template <int D>
KeyHash hash_key(const BoxKey<D>& k) {
  // Polynomial over (level, q >> 2, q & 1) with odd multipliers, then one splitmix64
  // finaliser. q >> 2 is the parent cell (for aligned keys), bit 1 of q the child
  // index, bit 0 marks unaligned (merged) origins.
  std::uint64_t x = static_cast<std::uint64_t>(k.level) + 1;
  unsigned sub = 0;
  for (int a = 0; a < D; ++a) {
    x = x * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(k.q[a] >> 2);
    x = x * 0xD6E8FEB86659FD93ull + static_cast<std::uint64_t>(k.q[a] & 1);
    sub |= static_cast<unsigned>((k.q[a] >> 1) & 1) << a;
  }
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  x ^= x >> 31;
  return KeyHash{x + sub, static_cast<std::uint32_t>(x >> 32) ^ (sub * 0x9E3779B9u)};
}

// Hash of child c of an aligned key k from the hash of its child 0: the children
// of one cell share the mixed part of hash_key (q >> 2 is k's cell, q & 1 = 0) and
// differ only in the child index (sub = c), so
// hash_key(k.child(c)) == sibling_hash(hash_key(k.child(0)), c). split() hashes once.
inline KeyHash sibling_hash(KeyHash first, unsigned c) {
  return KeyHash{first.pos + c, first.tag ^ (c * 0x9E3779B9u)};
}

// z-order ("Morton") comparison of two box origins, with axis 0 the least
// significant interleaved bit (so the children of a box are in z-order by index).
// Compares the origins only; callers break ties.
template <int D>
bool morton_less(const BoxKey<D>& a, const BoxKey<D>& b) {
  std::array<std::uint64_t, D> la{}, lb{};
  for (int i = 0; i < D; ++i) {
    la[i] = static_cast<std::uint64_t>(a.fine_lo(i));
    lb[i] = static_cast<std::uint64_t>(b.fine_lo(i));
  }
  int best = D - 1;
  std::uint64_t best_x = la[D - 1] ^ lb[D - 1];
  for (int i = D - 2; i >= 0; --i) {
    const std::uint64_t x = la[i] ^ lb[i];
    // x has a strictly higher most significant bit than best_x.
    if (best_x < x && best_x < (best_x ^ x)) {
      best = i;
      best_x = x;
    }
  }
  return la[best] < lb[best];
}

// Closed cubes of a and b intersect (share at least a point).
template <int D>
bool closed_intersect(const BoxKey<D>& a, const BoxKey<D>& b) {
  for (int i = 0; i < D; ++i) {
    const std::int64_t alo = a.fine_lo(i), blo = b.fine_lo(i);
    if (alo > blo + b.fine_side() || blo > alo + a.fine_side()) return false;
  }
  return true;
}

// Open cubes of a and b intersect (the boxes overlap in a set of full dimension).
template <int D>
bool open_intersect(const BoxKey<D>& a, const BoxKey<D>& b) {
  for (int i = 0; i < D; ++i) {
    const std::int64_t alo = a.fine_lo(i), blo = b.fine_lo(i);
    if (alo >= blo + b.fine_side() || blo >= alo + a.fine_side()) return false;
  }
  return true;
}

}  // namespace detail
}  // namespace pqmesh
