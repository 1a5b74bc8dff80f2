#pragma once
// Member definitions of Tree<D> (included at the end of tree/tree.hpp).
#include <cstddef>
#include <limits>

namespace pqmesh {

template <int D>
Tree<D>::Tree(const RootCube<D>& root) : root_(root) {
  int e = 0;
  const double mant = std::isfinite(root.size) && root.size > 0 ? std::frexp(root.size, &e) : 0.0;
  if (mant != 0.5) throw InternalError("tree: root size must be a positive power of two");
  root_exp_ = e - 1;  // size = 2^(e-1)
  const double half = std::ldexp(1.0, root_exp_ - 1);
  std::int64_t worst = 0;
  for (int a = 0; a < D; ++a) {
    const double m = root.origin[a] / half;  // exact: half is a power of two
    if (!std::isfinite(m) || m != std::floor(m) || std::fabs(m) >= 0x1p50)
      throw InternalError("tree: root origin along axis " + std::to_string(a) +
                          " is not a (modest) integer multiple of half the root size");
    root_m_[a] = static_cast<std::int64_t>(m);
    worst = std::max(worst, root_m_[a] < 0 ? -root_m_[a] : root_m_[a]);
  }
  // Planes at level L are (S / 2^(L+1)) * N with |N| <= (|m| + 2) * 2^L; exact when
  // |N| <= 2^53 and the scale stays a normal double.
  max_level_ = kTreeMaxLevel;
  while (max_level_ > 0 &&
         (worst + 2 > (std::int64_t{1} << (53 - max_level_)) || root_exp_ - max_level_ - 1 < -1021))
    --max_level_;
  // Generic grid (root_cube.hpp choose_generic_root_cube): every plane is
  // shifted by offset[a] = K * 2^ge. Planes stay integers times 2^ge when the
  // spacing at max_level_ is at least 2^(ge+1), and exact doubles when their
  // magnitude (root and extended box: max(|origin - 2S|, |origin + 3S|) + |offset|) is <= 2^(53+ge).
  for (int a = 0; a < D; ++a) {
    const double off = root.offset[a];
    root_off_[a] = off;
    if (off == 0) continue;
    if (!std::isfinite(off)) throw InternalError("tree: root offset is not finite");
    int oe = 0;
    std::frexp(off, &oe);
    int ge = oe - 53;  // off is an integer times 2^ge; raise ge to off's lowest set bit
    while (std::ldexp(off, -(ge + 1)) == std::floor(std::ldexp(off, -(ge + 1)))) ++ge;
    while (max_level_ > 0 && root_exp_ - max_level_ - 1 < ge + 1) --max_level_;
    // Planes run from origin - 2S to origin + 3S (root and extended box);
    // never more than choose_generic_root_cube's bound.
    const double reach = std::fmax(std::fabs(root.origin[a] - 2 * root.size), std::fabs(root.origin[a] + 3 * root.size)) +
                         std::fabs(off);
    if (!(reach <= std::ldexp(1.0, 53 + ge)))
      throw InternalError("tree: root offset along axis " + std::to_string(a) + " is too fine for exact box planes");
  }
  for (std::int32_t l = 0; l <= max_level_; ++l) half_side_[static_cast<std::size_t>(l)] = std::ldexp(1.0, root_exp_ - l - 1);
  nodes_.push_back(Node{});
  link_key_new(0, 0, detail::hash_key(at(0).key));
  leaf_count_ = 1;
}

template <int D>
inline double Tree<D>::key_plane(const Key& k, int axis, bool upper) const {
  const std::int64_t n = (root_m_[axis] << k.level) + k.q[axis] + (upper ? 2 : 0);
  if (k.level <= max_level_) return static_cast<double>(n) * half_side_[static_cast<std::size_t>(k.level)] + root_off_[axis];
  return std::ldexp(static_cast<double>(n), root_exp_ - k.level - 1) + root_off_[axis];
}

template <int D>
inline typename Tree<D>::Box Tree<D>::box(std::int32_t n) const {
  Box b;
  const Key& k = key(n);
  for (int a = 0; a < D; ++a) {
    b.lo[a] = key_plane(k, a, false);
    b.hi[a] = key_plane(k, a, true);
  }
  return b;
}

template <int D>
typename Tree<D>::Box Tree<D>::extended_box(std::int32_t n, int margin) const {
  Box b = box(n);
  const double h2 = margin * side(n);  // exact: a small integer times a power of two
  for (int a = 0; a < D; ++a) {
    b.lo[a] -= h2;  // exact: integer multiples of h / 2 well inside 53 bits
    b.hi[a] += h2;
  }
  return b;
}

template <int D>
std::int32_t Tree<D>::find(const Key& k) const {
  return index_.find(detail::hash_key(k), [&](std::int32_t id) { return at(id).key == k; });
}

template <int D>
std::int32_t Tree<D>::link_key_new(std::int32_t id, std::uint8_t inherit, detail::KeyHash h) {
  at(id).flags |= inherit;
  at(id).head = id;
  index_.insert(h, id, [&](std::int32_t x) { return detail::hash_key(at(x).key); });
  return id;
}

template <int D>
std::int32_t Tree<D>::link_key(std::int32_t id, std::uint8_t inherit) {
  const Key& k = at(id).key;
  const detail::KeyHash h = detail::hash_key(k);
  const std::int32_t head = index_.find(h, [&](std::int32_t x) { return at(x).key == k; });
  if (head < 0) return link_key_new(id, inherit, h);
  at(id).head = head;
  std::int32_t tail = head;
  while (at(tail).next_same >= 0) tail = at(tail).next_same;
  at(tail).next_same = id;
  return head;
}

template <int D>
bool Tree<D>::any_split(std::int32_t head) const {
  for (std::int32_t n = head; n >= 0; n = at(n).next_same)
    if (at(n).state == BoxState::Split) return true;
  return false;
}

template <int D>
void Tree<D>::update_mixed(std::int32_t head) {
  if (at(head).flags & kMixedFlag) return;
  bool split = false, other = false;
  for (std::int32_t n = head; n >= 0; n = at(n).next_same) (at(n).state == BoxState::Split ? split : other) = true;
  if (!(split && other)) return;
  at(head).flags |= kMixedFlag;
  mark_below(head);
}

template <int D>
void Tree<D>::mark_below(std::int32_t head) {
  std::vector<std::int32_t> stack{head};
  while (!stack.empty()) {
    const std::int32_t h = stack.back();
    stack.pop_back();
    if (!any_split(h)) continue;
    for (int k = 0; k < kChildren; ++k) {
      const std::int32_t c = find(at(h).key.child(k));
      if (c < 0) throw InternalError("tree: child key of a split box is missing");
      if (at(c).flags & kBelowMixedFlag) continue;  // its descendants are marked already
      at(c).flags |= kBelowMixedFlag;
      stack.push_back(c);
    }
  }
}

template <int D>
std::int32_t Tree<D>::split(std::int32_t n) {
  const Node& nd = node(n);
  if (nd.state != BoxState::Leaf) throw InternalError("tree: split of node " + std::to_string(n) + ", not a leaf");
  if (nd.flags & kMergedFlag)
    throw InternalError("tree: split of merged box " + std::to_string(n) + " (merged boxes are final)");
  if (nd.key.level >= max_level_)
    throw InternalError("tree: split of node " + std::to_string(n) + " would exceed the deepest exact level " +
                        std::to_string(max_level_));
  const Key k = nd.key;
  const std::int32_t head = nd.head;
  const std::uint8_t inherit = (at(head).flags & (kMixedFlag | kBelowMixedFlag)) ? kBelowMixedFlag : 0;
  // Child keys can already exist only if another node with this key was split
  // before (a merged box at an aligned child key needs absorbed grandchildren, whose
  // parents are those child keys), so a key with a single node skips the lookups.
  const bool fresh = at(head).next_same < 0;
  const detail::KeyHash h0 = detail::hash_key(k.child(0));  // the others: sibling_hash
  const auto first = static_cast<std::int32_t>(nodes_.size());
  for (int c = 0; c < kChildren; ++c) {
    Node child;
    child.key = k.child(c);
    child.parent = n;
    nodes_.push_back(child);
    const std::int32_t id = first + c;
    if (fresh) {
      link_key_new(id, inherit, detail::sibling_hash(h0, static_cast<unsigned>(c)));
    } else {
      const std::int32_t h = link_key(id, inherit);
      if (h != id) update_mixed(h);
    }
  }
  at(n).state = BoxState::Split;
  at(n).first_child = first;
  leaf_count_ += kChildren - 1;
  update_mixed(head);
  return first;
}

template <int D>
std::int32_t Tree<D>::duplicate(std::int32_t n, std::int32_t component) {
  const Node& nd = node(n);
  if (nd.state != BoxState::Leaf)
    throw InternalError("tree: duplicate of node " + std::to_string(n) + ", not a leaf");
  Node dup;
  dup.key = nd.key;
  dup.parent = nd.parent;
  dup.component = component;
  dup.flags = (nd.flags & kMergedFlag) ? (kMergedFlag | kProtectedFlag) : 0;
  nodes_.push_back(dup);
  const auto id = static_cast<std::int32_t>(nodes_.size() - 1);
  update_mixed(link_key(id, 0));
  ++leaf_count_;
  return id;
}

template <int D>
std::int32_t Tree<D>::merge(std::span<const std::int32_t> boxes, std::int32_t component) {
  auto fail = [&](const std::string& why) {
    std::string ids;
    for (std::int32_t b : boxes) {
      if (!ids.empty()) ids += ',';
      ids += std::to_string(b);
    }
    throw InternalError("tree: merge of boxes {" + ids + "}: " + why);
  };
  if (boxes.size() < static_cast<std::size_t>(kChildren)) fail("fewer than 2^D boxes");
  std::vector<std::int32_t> sorted(boxes.begin(), boxes.end());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) fail("a box is listed twice");
  const std::int32_t lev = node(boxes[0]).key.level;
  if (lev < 1) fail("the root cannot be merged");
  std::array<std::int64_t, D> c0{};
  c0.fill(std::numeric_limits<std::int64_t>::max());
  for (std::int32_t b : boxes) {
    const Node& nd = node(b);
    if (nd.state != BoxState::Leaf || (nd.flags & kMergedFlag) || nd.key.level != lev || !nd.key.aligned())
      fail("box " + std::to_string(b) + " is not a tree-aligned leaf of level " + std::to_string(lev));
    for (int a = 0; a < D; ++a) c0[a] = std::min(c0[a], nd.key.q[a] / 2);
  }
  unsigned covered = 0;
  for (std::int32_t b : boxes) {
    int cell = 0;
    for (int a = 0; a < D; ++a) {
      const std::int64_t off = at(b).key.q[a] / 2 - c0[a];
      if (off > 1) fail("the boxes do not fit in a 2^D block");
      cell |= static_cast<int>(off) << a;
    }
    covered |= 1u << cell;
  }
  if (covered != (1u << kChildren) - 1) fail("the boxes do not cover a full 2^D block");
  Node m;
  m.key.level = lev - 1;
  m.key.q = c0;  // units of h(lev), half the merged side
  m.component = component;
  m.flags = kMergedFlag | kProtectedFlag;
  nodes_.push_back(m);
  const auto id = static_cast<std::int32_t>(nodes_.size() - 1);
  for (std::int32_t b : boxes) {
    at(b).state = BoxState::Absorbed;
    at(b).absorbed_into = id;
  }
  // If the block is aligned, the merged key equals the key of the split parent cell,
  // which then becomes mixed.
  update_mixed(link_key(id, 0));
  leaf_count_ += 1 - static_cast<std::int32_t>(boxes.size());
  ++merged_count_;
  return id;
}

template <int D>
std::vector<std::int32_t> Tree<D>::leaves() const {
  std::vector<std::int32_t> out;
  out.reserve(static_cast<std::size_t>(leaf_count_));
  for (std::int32_t n = 0; n < size(); ++n)
    if (at(n).state == BoxState::Leaf) out.push_back(n);
  std::sort(out.begin(), out.end(), [&](std::int32_t a, std::int32_t b) {
    const Node& x = at(a);
    const Node& y = at(b);
    if (detail::morton_less(x.key, y.key)) return true;
    if (detail::morton_less(y.key, x.key)) return false;
    if (x.key.level != y.key.level) return x.key.level < y.key.level;
    if (x.component != y.component) return x.component < y.component;
    return a < b;
  });
  return out;
}

template <int D>
void Tree<D>::collect_key(std::int32_t head, std::vector<std::int32_t>& out) const {
  for (std::int32_t n = head; n >= 0; n = at(n).next_same) {
    const Node& nd = at(n);
    if (nd.state == BoxState::Leaf) {
      out.push_back(n);
    } else if (nd.state == BoxState::Absorbed) {
      // The merged box and its duplicates (same key). An aligned merged key can also
      // hold plain duplicates of the same cube; they are leaves of the same cube and
      // the caller's geometric filter treats them exactly like the merged box.
      const std::int32_t mh = at(nd.absorbed_into).head;
      for (std::int32_t m = mh; m >= 0; m = at(m).next_same)
        if (at(m).state == BoxState::Leaf) out.push_back(m);
    }
  }
}

template <int D>
void Tree<D>::descend(std::int32_t head, const Key& region, Mode mode, std::vector<std::int32_t>& out) const {
  if (!any_split(head)) return;
  std::vector<std::int32_t> stack{head};
  while (!stack.empty()) {
    const std::int32_t h = stack.back();
    stack.pop_back();
    if (!any_split(h)) continue;
    const Key k = at(h).key;
    for (int c = 0; c < kChildren; ++c) {
      const Key ck = k.child(c);
      const bool wanted = mode == Mode::Overlapping ? detail::open_intersect(ck, region)
                                                    : detail::closed_intersect(ck, region);
      if (!wanted) continue;
      const std::int32_t ch = find(ck);
      if (ch < 0) throw InternalError("tree: child key of a split box is missing");
      collect_key(ch, out);
      stack.push_back(ch);
    }
  }
}

// Candidates from one cell of the level-`lev` grid: the leaves at the cell's own key,
// leaves below it (when the mode descends), and leaves at ancestor keys containing
// it (the first existing ancestor if the cell's key is absent, then further up while
// kBelowMixedFlag says an ancestor may hold a duplicate leaf).
template <int D>
void Tree<D>::visit_cell(std::int32_t lev, const std::array<std::int64_t, D>& cell, const Key& region, Mode mode,
                         std::vector<std::int32_t>& out, std::vector<std::int32_t>& visited) const {
  Key k = Key::cell(lev, cell);
  std::int32_t h = find(k);
  if (h >= 0) {
    collect_key(h, out);
    if (mode != Mode::LargerNeighbours) descend(h, region, mode, out);
  } else {
    do {  // the root key always exists, so this stops
      k = parent_cell(k);
      h = find(k);
    } while (h < 0);
    collect_key(h, out);
  }
  while (at(h).flags & kBelowMixedFlag) {
    k = parent_cell(k);
    h = find(k);
    if (std::find(visited.begin(), visited.end(), h) != visited.end()) break;  // walked from there already
    visited.push_back(h);
    collect_key(h, out);
  }
}

template <int D>
void Tree<D>::gather(std::int32_t n, Mode mode, std::vector<std::int32_t>& out) const {
  out.clear();
  if (node(n).state != BoxState::Leaf)
    throw InternalError("tree: neighbour query on node " + std::to_string(n) + ", not a leaf");
  const Key region = at(n).key;
  // The region as a block of w^D cells of the level-`lev` grid starting at `lo`.
  const bool aligned = region.aligned();
  const std::int32_t lev = aligned ? region.level : region.level + 1;
  const std::int64_t w = aligned ? 1 : 2;
  std::array<std::int64_t, D> lo{};
  for (int a = 0; a < D; ++a) lo[a] = aligned ? region.q[a] / 2 : region.q[a];
  const std::int64_t cells = std::int64_t{1} << lev;
  std::vector<std::int32_t> visited;
  std::array<std::int64_t, D> cell{};
  if (mode == Mode::LargerNeighbours && aligned && merged_count_ == 0) {
    // A larger neighbour is a union of level-(L-1) cells, one of which touches the
    // box; it is not the box's parent cell P (that would overlap the box), and along
    // each axis it lies on the side of P where the box sits (the other side is h(L)
    // away). So only P + delta, delta_a in {0, side_a}, delta != 0, need a visit:
    // 2^D - 1 cells instead of 3^D - 1. Not valid once merged boxes exist: a merged
    // box of level L-1 is a union of level-L cells only, so then the full ring is
    // visited.
    if (region.level == 0) return;
    std::array<std::int64_t, D> parent{}, side{};
    for (int a = 0; a < D; ++a) {
      parent[a] = lo[a] >> 1;
      side[a] = (lo[a] & 1) ? 1 : -1;
    }
    const std::int64_t pcells = cells >> 1;
    for (int m = 1; m < kChildren; ++m) {
      bool inside_root = true;
      for (int a = 0; a < D; ++a) {
        cell[a] = parent[a] + (((m >> a) & 1) ? side[a] : 0);
        inside_root = inside_root && cell[a] >= 0 && cell[a] < pcells;
      }
      if (inside_root) visit_cell(lev - 1, cell, region, mode, out, visited);
    }
  } else if (mode == Mode::Overlapping) {
    // The region's own cells.
    for (std::int64_t idx = 0; idx < (w == 1 ? 1 : kChildren); ++idx) {
      for (int a = 0; a < D; ++a) cell[a] = lo[a] + ((idx >> a) & 1);
      visit_cell(lev, cell, region, mode, out, visited);
    }
  } else {
    // The ring of cells around the region: every neighbour meets one of them.
    const std::int64_t span = w + 2;
    std::int64_t total = 1;
    for (int a = 0; a < D; ++a) total *= span;
    for (std::int64_t idx = 0; idx < total; ++idx) {
      std::int64_t t = idx;
      bool inner = true, inside_root = true;
      for (int a = 0; a < D; ++a) {
        const std::int64_t off = t % span;
        t /= span;
        cell[a] = lo[a] - 1 + off;
        inner = inner && off >= 1 && off <= w;
        inside_root = inside_root && cell[a] >= 0 && cell[a] < cells;
      }
      if (inner || !inside_root) continue;
      visit_cell(lev, cell, region, mode, out, visited);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  std::erase_if(out, [&](std::int32_t x) {
    if (x == n) return true;
    const Key& k = at(x).key;
    if (mode == Mode::Overlapping) return !detail::open_intersect(k, region);
    if (!detail::closed_intersect(k, region) || detail::open_intersect(k, region)) return true;
    return mode == Mode::LargerNeighbours && k.level >= region.level;
  });
}

template <int D>
void Tree<D>::neighbours(std::int32_t n, std::vector<std::int32_t>& out) const {
  gather(n, Mode::AllNeighbours, out);
}

template <int D>
void Tree<D>::larger_neighbours(std::int32_t n, std::vector<std::int32_t>& out) const {
  gather(n, Mode::LargerNeighbours, out);
}

template <int D>
void Tree<D>::overlapping(std::int32_t n, std::vector<std::int32_t>& out) const {
  gather(n, Mode::Overlapping, out);
}

template <int D>
bool Tree<D>::closed_contains(const Key& k, const Point& p) const {
  for (int a = 0; a < D; ++a)  // exact comparisons: planes are exact doubles
    if (!(key_plane(k, a, false) <= p[a] && p[a] <= key_plane(k, a, true))) return false;
  return true;
}

template <int D>
void Tree<D>::leaves_containing(const Point& p, std::vector<std::int32_t>& out) const {
  out.clear();
  if (!closed_contains(at(0).key, p)) return;
  // Depth-first over the keys whose closed cube holds p. A pop pushes at most
  // 2^D children and keys exist down to level kTreeMaxLevel at most, so the
  // stack never holds more than 1 + (2^D - 1) (kTreeMaxLevel + 1) keys.
  std::array<std::int32_t, 1 + (kChildren - 1) * (kTreeMaxLevel + 1)> stack;
  std::size_t top = 0;
  stack[top++] = 0;  // node 0 is the head of the root key
  while (top > 0) {
    const std::int32_t h = stack[--top];
    collect_key(h, out);
    if (!any_split(h)) continue;
    // p lies in the closed cube of h, so child c holds p iff p is on the
    // child's side of each mid-plane (or on it). The mid-plane is the child's
    // own plane, the same exact double closed_contains would compare with.
    const Key& k = at(h).key;
    std::array<bool, D> low{}, high{};
    for (int a = 0; a < D; ++a) {
      const double mid = key_plane(k.child(1 << a), a, false);
      low[a] = p[a] <= mid;
      high[a] = p[a] >= mid;
    }
    for (int c = 0; c < kChildren; ++c) {
      bool holds = true;
      for (int a = 0; a < D; ++a) holds = holds && (((c >> a) & 1) ? high[a] : low[a]);
      if (holds) stack[top++] = find(k.child(c));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  std::erase_if(out, [&](std::int32_t x) { return !closed_contains(at(x).key, p); });
}

template <int D>
template <class Adjacent, class AfterSplit>
std::int64_t Tree<D>::balance(std::span<const std::int32_t> seeds, Adjacent adjacent, AfterSplit after_split) {
  std::vector<std::int32_t> work(seeds.begin(), seeds.end());
  std::vector<std::int32_t> big;
  std::int64_t splits = 0;
  for (std::size_t next = 0; next < work.size(); ++next) {
    const std::int32_t s = work[next];
    bool changed = true;
    // Repeat: splitting a neighbour 2^k times larger leaves children 2^(k-1) times
    // larger, which may still violate the condition against s.
    while (changed && node(s).state == BoxState::Leaf) {
      changed = false;
      larger_neighbours(s, big);
      for (std::int32_t b : big) {
        const Node& nb = at(b);
        if (nb.state != BoxState::Leaf || nb.key.level >= at(s).key.level - 1) continue;
        if (nb.flags & (kProtectedFlag | kMergedFlag)) continue;
        if (!adjacent(b, s)) continue;
        const std::int32_t before = size();
        const std::int32_t first = split(b);
        ++splits;
        after_split(b, first);
        for (std::int32_t id = before; id < size(); ++id)
          if (at(id).state == BoxState::Leaf) work.push_back(id);
        changed = true;
      }
    }
  }
  return splits;
}

template <int D>
template <class Adjacent, class AfterSplit>
std::int64_t Tree<D>::balance_all(Adjacent adjacent, AfterSplit after_split) {
  std::vector<std::int32_t> seeds;
  seeds.reserve(static_cast<std::size_t>(leaf_count_));
  for (std::int32_t n = 0; n < size(); ++n)
    if (at(n).state == BoxState::Leaf) seeds.push_back(n);
  return balance(seeds, adjacent, after_split);
}

}  // namespace pqmesh
