#pragma once
// The table of warped grid points (thesis §4.3; built by warp.hpp): grid
// point -> moved coordinates, with the counts of the moves not made. Every
// mesh vertex named by a grid point resolves through it (point_book.hpp), so
// all boxes sharing a point see one moved copy.
//
// Fig. 4.7 copies (§4.3, "the special sharing case"): a box vertex in the
// thin exterior slot of a reflex edge E, within h/16 of both its facets F
// and G, has no single entry but up to one copy per facet, each warped h/16
// away from its own facet. Such a vertex is outside P (beyond both planes),
// so it is never a mesh vertex: a copy serves only as the end point of ring
// segments cut by its facet (the crossing of F is constructed from F's copy,
// of G from G's copy), i.e. the portion for the box on F's side is used for
// P ∧ b and ignored for P ∧ c. Every decision (sides, orders) is still made
// on the prewarped point, which each copy leaves unchanged for its facet
// (warp.cpp).
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "pqmesh/vec.hpp"
#include "tet3d/points/first_use_index.hpp"
#include "tet3d/points/grid_point.hpp"

namespace pqmesh::tet3d {

struct Warp {
  int facet = -1;  // the key's facet (the first close facet), -1 for none
  Vec3 at;
};

class WarpTable {
 public:
  // Every grid point of every box is looked up here (grid_vertex) and few are
  // warped, so most finds miss: the flat index ends a miss in its slot array.
  // The pointer stays valid until the next insert.
  const Warp* find(const GridPoint& p) const {
    const int id = index_.find(p);
    return id < 0 ? nullptr : &warps_[static_cast<std::size_t>(id)];
  }
  // False (and no change) when p already has a warp.
  bool insert(const GridPoint& p, const Warp& w) {
    const bool fresh = index_.insert(p).second;
    if (fresh) warps_.push_back(w);
    return fresh;
  }
  // Fig. 4.7: the copy of p warped for facet f (p has no entry then).
  bool insert_copy(const GridPoint& p, int facet, Vec3 at) { return copies_.try_emplace({p, facet}, at).second; }
  const Vec3* find_copy(const GridPoint& p, int facet) const {
    const auto it = copies_.find({p, facet});
    return it == copies_.end() ? nullptr : &it->second;
  }
  // The coordinates of ring point p as an end point of a segment cut by
  // facet f: its copy for f if built, else `current` (its entry or the
  // prewarped point, as the caller resolved it).
  Vec3 at_for_cut(const GridPoint& p, int facet, Vec3 current) const {
    if (copies_.empty()) return current;
    const Vec3* c = find_copy(p, facet);
    return c != nullptr ? *c : current;
  }
  // Whether p was moved at all (an entry or a copy): the points a freeze
  // round (facet_boxes.cpp) may blame.
  bool moved(const GridPoint& p) const {
    if (index_.find(p) >= 0) return true;
    if (copies_.empty()) return false;
    for (const auto& [key, at] : copies_)
      if (key.first == p) return true;
    return false;
  }
  // Every entry as f(p, warp), in insertion order.
  template <class F>
  void for_each(F f) const {
    for (int id = 0; id < index_.size(); ++id) f(index_.key(id), warps_[static_cast<std::size_t>(id)]);
  }
  // Every Fig. 4.7 copy as f(p, facet, at), in no particular order.
  template <class F>
  void for_each_copy(F f) const {
    for (const auto& [key, at] : copies_) f(key.first, key.second, at);
  }
  std::size_t size() const { return warps_.size(); }
  std::size_t copy_count() const { return copies_.size(); }
  std::int64_t conflicts = 0;     // left: the move would change a side decision
  std::int64_t bisected = 0;      // moved onto the bisector of an acute wedge (among size())
  std::int64_t reflex_left = 0;   // close to both facets of a reflex edge, in its slot, and some copy not built (Fig. 4.7)
  std::int64_t reflex_copied = 0; // close to both facets of a reflex edge, in its slot: both Fig. 4.7 copies built
  std::int64_t crowded_left = 0;  // left: close to two facets outside P / without a common edge / to three
  std::int64_t on_plane = 0;      // not moved: exactly on a facet plane
  std::int64_t first_pass = 0;     // moved with a first-pass part (among size())
  std::int64_t fallback = 0;       // moved by a fallback (first pass only / second only; among size())
  std::int64_t parallel = 0;       // first-pass moves of box-edge pieces parallel to E (among the moves)
  std::int64_t parallel_left = 0;  // first-pass moves not made: E on the box edge's line
  std::int64_t frozen_left = 0;   // left: in the caller's frozen set (their move inverted a tetrahedron)
  std::int64_t centres = 0;       // square centres carried with their corners (among size())
  std::int64_t shortened = 0;     // moved by 1/2..1/16 of a refused second-pass move (among size())
  std::int64_t out_of_face = 0;   // reported points that kept a move out of the reporting box (among size())
  std::int64_t out_of_face_left = 0;  // reported points whose move out of the reporting box was dropped
  // Every count above (a rebuild copies each point's share of them:
  // warp.hpp WarpJournal).
  static constexpr std::int64_t WarpTable::*kCounts[] = {
      &WarpTable::conflicts,   &WarpTable::bisected,      &WarpTable::reflex_left,   &WarpTable::reflex_copied,
      &WarpTable::crowded_left, &WarpTable::on_plane,     &WarpTable::first_pass,    &WarpTable::fallback,
      &WarpTable::parallel,    &WarpTable::parallel_left, &WarpTable::frozen_left,   &WarpTable::centres,
      &WarpTable::shortened,   &WarpTable::out_of_face,   &WarpTable::out_of_face_left};

 private:
  struct CopyHash {
    std::size_t operator()(const std::pair<GridPoint, int>& k) const {
      return GridPointHash{}(k.first) * 31u + static_cast<std::size_t>(k.second + 1);
    }
  };
  FirstUseIndex<GridPoint, GridPointHash> index_;
  std::vector<Warp> warps_;  // by index_ id
  std::unordered_map<std::pair<GridPoint, int>, Vec3, CopyHash> copies_;  // Fig. 4.7, (p, facet) -> coordinates
};

}  // namespace pqmesh::tet3d
