#pragma once
// Integer-keyed quadtree (D = 2) / octree (D = 3) shared by the meshers
// (docs/ARCHITECTURE.md "Modules and dependencies"; thesis §4.1.1-4.1.3). Header-only
// template; src/tree/tree.cpp instantiates D = 2, 3.
//
// Boxes. Every node is a box with a BoxKey (tree/key.hpp): a level L (side h(L) =
// S / 2^L) and an origin on the h(L+1) grid. Real coordinates are dyadic and every
// box plane is an exact double (tree/root_cube.hpp), so a mesher can compare a point
// coordinate with a box plane exactly.
//
// Node states.
//   Leaf      a box of the current subdivision (also a merged box, see below);
//   Split     has 2^D children, stored as a contiguous block of ids first_child + k,
//             k in z-order (bit a of k = upper half along axis a);
//   Absorbed  a former leaf that vertex centering united into a merged box
//             (absorbed_into(n)); it stays in the tree so that key navigation
//             through its cube still reaches the merged box.
//
// Duplicates (thesis §4.1.1). Several nodes may carry the same key, one per connected
// component of P ∩ cube; the mesher creates them with duplicate() and numbers the
// components with component(). Each key maps (through a flat hash index) to the
// list of its nodes in creation order. A duplicate may be split on its own; its
// children get the same keys as the children of any other split duplicate, so all
// navigation is by key, never by parent pointers.
//
// Merged boxes (thesis §4.1.3, vertex centering, Fig. 4.3: "uniting"). merge() unites a 2x2(x2)
// block of same-level leaves (plus, optionally, duplicates of those cells) into one
// new leaf of twice the side. The block may start at any cell, so the merged box is
// in general NOT a tree cell: its key has level L-1 and an origin q on the level-L
// grid (q odd allowed; see key.hpp). A merged box has no parent, is protected, and
// cannot be split (the thesis never splits it: "From now on, B is protected").
//
// Neighbours (thesis §4.1.1: "embeddings intersect non-trivially, and one is not a
// duplicate of the other"). We define: leaf b' is a neighbour of leaf b iff their
// closed cubes intersect (a shared facet, edge, or only a corner all count) and their
// open cubes are disjoint. Leaves whose open cubes overlap are duplicates of each
// other or descendants of different duplicates of one cube; they are never
// neighbours and are reported by overlapping() instead.
//
// Queries. A neighbour query visits the ring of grid cells around the box (3^D - 1
// cells of its own level; 4^D - 2^D cells of the next finer level for an unaligned
// merged box). For each cell it looks up the cell's key and takes the leaves there,
// descends through split nodes to the smaller leaves touching the box, or walks up
// to the first existing ancestor key (the larger leaf containing the cell). Absorbed
// nodes forward to their merged box. Candidates are then filtered by exact integer
// geometry (key.hpp), so the result does not depend on how they were found. In a
// balanced tree a query costs O(3^D) hash lookups.
//
// Balance (thesis §4.1.1): "no box is balance-adjacent to a box more than twice its
// size". Balance-adjacency needs P, so the mesher supplies it as a callback; the tree
// splits unprotected leaves with a worklist (balance()).
//
// Determinism: ids are assigned in creation order, the hash index is never iterated,
// and every query returns its ids sorted ascending, so the same operations give the
// same ids and the same answers.
//
// Thread safety: const queries do not modify the tree and may run concurrently.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pqmesh/errors.hpp"
#include "tree/chunked_vector.hpp"
#include "tree/key.hpp"
#include "tree/key_index.hpp"
#include "tree/root_cube.hpp"

namespace pqmesh {

enum class BoxState : std::uint8_t { Leaf, Split, Absorbed };

// Default balance-adjacency: every pair of neighbouring leaves.
struct AllBalanceAdjacent {
  bool operator()(std::int32_t /*big*/, std::int32_t /*small*/) const { return true; }
};
// Default hook after balance() splits a box: nothing to do.
struct NoSplitHook {
  void operator()(std::int32_t /*node*/, std::int32_t /*first_child*/) const {}
};

template <int D>
class Tree {
 public:
  static constexpr int kChildren = 1 << D;
  using Key = BoxKey<D>;
  using Point = std::array<double, D>;
  struct Box {
    Point lo{}, hi{};
  };

  // A tree with a single leaf, the root (id 0, component 0). Throws InternalError if
  // the root size is not a power of two or its origin not a multiple of size / 2.
  explicit Tree(const RootCube<D>& root);

  // ---- whole tree
  const RootCube<D>& root() const { return root_; }
  std::int32_t size() const { return static_cast<std::int32_t>(nodes_.size()); }  // ids are 0..size()-1
  std::int32_t leaf_count() const { return leaf_count_; }  // nodes in state Leaf
  // Capacity hint: room for `nodes` nodes without reallocation.
  void reserve(std::int32_t nodes) {
    nodes_.reserve(static_cast<std::size_t>(nodes));
    index_.reserve(static_cast<std::size_t>(nodes), [&](std::int32_t x) { return detail::hash_key(at(x).key); });
  }
  // Performance hint, no effect on the tree or its ids: leaf n is likely to be
  // split soon, so the index slots of its children's keys are fetched into cache
  // now (a mesher walking a work list calls it a few nodes ahead). Ignores bad ids.
  void prefetch_split(std::int32_t n) const {
    if (n >= 0 && n < size()) index_.prefetch(detail::hash_key(at(n).key.child(0)));
  }
  // Deepest level split() may create: box planes stay exact doubles down to it.
  std::int32_t max_level() const { return max_level_; }

  // ---- per node (references returned here stay valid while the tree grows)
  const Key& key(std::int32_t n) const { return node(n).key; }
  std::int32_t level(std::int32_t n) const { return node(n).key.level; }
  BoxState state(std::int32_t n) const { return node(n).state; }
  bool is_leaf(std::int32_t n) const { return node(n).state == BoxState::Leaf; }
  bool is_merged(std::int32_t n) const { return (node(n).flags & kMergedFlag) != 0; }
  // Parent of a box created by split() (or a duplicate of one); -1 for the root, its
  // duplicates and merged boxes.
  std::int32_t parent(std::int32_t n) const { return node(n).parent; }
  std::int32_t first_child(std::int32_t n) const { return node(n).first_child; }  // -1 unless Split
  std::int32_t absorbed_into(std::int32_t n) const { return node(n).absorbed_into; }  // -1 unless Absorbed
  // Next node with the same key (duplicates), in creation order; -1 at the end.
  std::int32_t next_same_key(std::int32_t n) const { return node(n).next_same; }
  std::int32_t component(std::int32_t n) const { return node(n).component; }
  void set_component(std::int32_t n, std::int32_t c) { node(n).component = c; }
  // Free integer for the mesher (index into its own parallel arrays); -1 initially.
  std::int32_t payload(std::int32_t n) const { return node(n).payload; }
  void set_payload(std::int32_t n, std::int32_t p) { node(n).payload = p; }
  // Protected boxes are never split by balance() (thesis §4.1.1, §4.1.3-4.1.4).
  bool is_protected(std::int32_t n) const { return (node(n).flags & kProtectedFlag) != 0; }
  void set_protected(std::int32_t n, bool p) {
    if (p)
      node(n).flags |= kProtectedFlag;
    else
      node(n).flags &= static_cast<std::uint8_t>(~kProtectedFlag);
  }

  // ---- exact geometry
  double side(std::int32_t n) const {
    const std::int32_t l = level(n);
    return l <= max_level_ ? 2 * half_side_[static_cast<std::size_t>(l)] : std::ldexp(1.0, root_exp_ - l);
  }
  // Lower (upper = false) or upper plane of the box along `axis`, an exact double.
  double plane(std::int32_t n, int axis, bool upper) const { return key_plane(key(n), axis, upper); }
  double key_plane(const Key& k, int axis, bool upper) const;
  Box box(std::int32_t n) const;
  // The extended box ex(b) of thesis §4.1.1: the concentric cube of 5 times the side,
  // [lo - 2h, hi + 2h] per axis (margin 2; margin m gives [lo - m h, hi + m h], m in
  // 1..4). Its planes are exact doubles as well (dyadic, same scale); it may reach
  // outside the root cube.
  Box extended_box(std::int32_t n, int margin = 2) const;

  // ---- structure
  // Splits leaf n into 2^D children (component 0, payload -1, unprotected) and
  // returns the id of the first; the children are first..first+2^D-1 in z-order.
  // Throws InternalError if n is not a leaf, is a merged box, or is at max_level().
  std::int32_t split(std::int32_t n);
  // New leaf with the same key (and parent) as leaf n, carrying `component`; a
  // duplicate of a merged box is itself a merged box (protected, unsplittable).
  std::int32_t duplicate(std::int32_t n, std::int32_t component);
  // Vertex centering (thesis §4.1.3): unites the given leaves, all of one level L >= 1
  // and covering exactly a 2x2(x2) block of level-L cells (every cell at least once;
  // several duplicates of a cell are allowed), into a new protected leaf of level L-1
  // whose origin is the block's lowest cell. The given leaves become Absorbed.
  std::int32_t merge(std::span<const std::int32_t> boxes, std::int32_t component = 0);

  // ---- queries (all results sorted by id)
  // Head of the node list of key k (then follow next_same_key), or -1.
  std::int32_t find(const Key& k) const;
  // All leaves in z-order of their origins (axis 0 least significant), then larger
  // boxes first, then component, then id.
  std::vector<std::int32_t> leaves() const;
  // Leaves whose closed cube contains p (all duplicates; several boxes when p is on
  // box planes). Empty if p is outside the root cube.
  void leaves_containing(const Point& p, std::vector<std::int32_t>& out) const;
  // Neighbours of leaf n (definition in the header comment), any sizes.
  void neighbours(std::int32_t n, std::vector<std::int32_t>& out) const;
  // Neighbours of leaf n that are strictly larger than n.
  void larger_neighbours(std::int32_t n, std::vector<std::int32_t>& out) const;
  // Leaves other than n whose open cube meets the open cube of leaf n.
  void overlapping(std::int32_t n, std::vector<std::int32_t>& out) const;

  std::vector<std::int32_t> neighbours(std::int32_t n) const {
    std::vector<std::int32_t> out;
    neighbours(n, out);
    return out;
  }
  std::vector<std::int32_t> leaves_containing(const Point& p) const {
    std::vector<std::int32_t> out;
    leaves_containing(p, out);
    return out;
  }

  // ---- balance (thesis §4.1.1 balance condition)
  // Assumption on `adjacent`: if (big, small) is not balance-adjacent, then neither
  // is (c, small) for a box c created later by splitting big (a child, or a
  // duplicate of a child, made by the hook for a component of (P ∧ big) ∩ child).
  // The thesis' definition has this property (P ∧ c ⊂ P ∧ big, ex(c) ⊂ ex(big));
  // without it a leaf already processed is not re-examined against new boxes.
  // Worklist balancing. Each seed (and every leaf created on the way) is checked
  // against its larger neighbours; a neighbour `big` more than twice the size of a
  // leaf `small` (level(big) < level(small) - 1) is split when it is not protected,
  // not a merged box, and adjacent(big, small) is true. After every split,
  // after_split(node, first_child) runs (the mesher assigns components, creates
  // duplicates, sets payloads) and every leaf created since, including duplicates
  // made by the hook, joins the worklist. Work is proportional to the number of
  // seeds plus splits. Returns the number of splits. Seeds that are not leaves are
  // ignored. Callbacks must not merge boxes.
  template <class Adjacent = AllBalanceAdjacent, class AfterSplit = NoSplitHook>
  std::int64_t balance(std::span<const std::int32_t> seeds, Adjacent adjacent = {},
                       AfterSplit after_split = {});
  // balance() seeded with every leaf, in id order.
  template <class Adjacent = AllBalanceAdjacent, class AfterSplit = NoSplitHook>
  std::int64_t balance_all(Adjacent adjacent = {}, AfterSplit after_split = {});

 private:
  static constexpr std::uint8_t kProtectedFlag = 1;
  static constexpr std::uint8_t kMergedFlag = 2;
  // Key-level flags, meaningful on the head node of a key's list only.
  // kMixedFlag: the key holds a Split node and a non-Split node (leaf or absorbed).
  // kBelowMixedFlag: some strict ancestor key is mixed. Invariant: once set on a key
  // it is set on all its descendant keys (children inherit it at creation, and
  // mark_below() walks existing descendants). Both flags only ever turn on.
  // Why: a leaf can only sit at a key that has descendant keys if that key is mixed,
  // so when walking up from a cell, ancestors can hold leaves only while the current
  // key has kBelowMixedFlag; otherwise the first existing key ends the walk.
  static constexpr std::uint8_t kMixedFlag = 4;
  static constexpr std::uint8_t kBelowMixedFlag = 8;

  struct Node {
    Key key;
    std::int32_t parent = -1;
    std::int32_t first_child = -1;
    std::int32_t next_same = -1;
    std::int32_t head = -1;  // first node with the same key (carries the key flags)
    std::int32_t absorbed_into = -1;
    std::int32_t component = 0;
    std::int32_t payload = -1;
    BoxState state = BoxState::Leaf;
    std::uint8_t flags = 0;
  };

  enum class Mode { AllNeighbours, LargerNeighbours, Overlapping };

  // Checked access. The throw lives in a separate cold function so that this
  // stays small enough to inline (every per-node query goes through it).
  const Node& node(std::int32_t n) const {
    if (n < 0 || n >= size()) [[unlikely]]
      throw_bad_node(n);
    return nodes_[static_cast<std::size_t>(n)];
  }
  Node& node(std::int32_t n) {
    if (n < 0 || n >= size()) [[unlikely]]
      throw_bad_node(n);
    return nodes_[static_cast<std::size_t>(n)];
  }
  [[noreturn, gnu::cold, gnu::noinline]] static void throw_bad_node(std::int32_t n) {
    throw InternalError("tree: node id " + std::to_string(n) + " out of range");
  }
  const Node& at(std::int32_t n) const { return nodes_[static_cast<std::size_t>(n)]; }
  Node& at(std::int32_t n) { return nodes_[static_cast<std::size_t>(n)]; }

  static Key parent_cell(const Key& k) {
    Key p;
    p.level = k.level - 1;
    for (int a = 0; a < D; ++a) p.q[a] = (k.q[a] >> 2) << 1;
    return p;
  }

  // Appends node `id` to its key's list; returns the head (== id for a new key).
  // A new key inherits kBelowMixedFlag as `inherit`.
  std::int32_t link_key(std::int32_t id, std::uint8_t inherit);
  // As link_key for a key known to be absent, whose hash is h.
  std::int32_t link_key_new(std::int32_t id, std::uint8_t inherit, detail::KeyHash h);
  bool any_split(std::int32_t head) const;
  void update_mixed(std::int32_t head);
  void mark_below(std::int32_t head);
  void collect_key(std::int32_t head, std::vector<std::int32_t>& out) const;
  void visit_cell(std::int32_t level, const std::array<std::int64_t, D>& cell, const Key& region, Mode mode,
                  std::vector<std::int32_t>& out, std::vector<std::int32_t>& visited) const;
  void descend(std::int32_t head, const Key& region, Mode mode, std::vector<std::int32_t>& out) const;
  void gather(std::int32_t n, Mode mode, std::vector<std::int32_t>& out) const;
  bool closed_contains(const Key& k, const Point& p) const;

  RootCube<D> root_;
  std::int64_t root_m_[D] = {};  // root origin / (S / 2), integers
  double root_off_[D] = {};      // RootCube::offset (generic grid), added to every plane
  int root_exp_ = 0;             // S = 2^root_exp_
  std::int32_t max_level_ = 0;
  // half_side_[L] = 2^(root_exp_ - L - 1), L <= max_level_: normal doubles, so
  // multiplying by them is exact (as std::ldexp, which is much slower).
  std::array<double, kTreeMaxLevel + 1> half_side_{};
  std::int32_t leaf_count_ = 0;
  std::int32_t merged_count_ = 0;  // merge() calls so far
  // The quadtree's nodes in huge-page slabs (chunked_vector.hpp): on the 2D plate
  // of docs/algorithm/quad2d.md "Speed and memory" (1.2 million nodes, 65 MB)
  // they took ~15k 4 KiB page faults, and the slabs go back to the system with
  // the tree. The octree keeps malloc chunks until slabs are measured on the 3D
  // runs.
  detail::ChunkedVector<Node, 13, D == 2> nodes_;
  detail::KeyIndex index_;
};

using QuadTree = Tree<2>;
using OctTree = Tree<3>;

}  // namespace pqmesh

#include "tree/tree_impl.hpp"
