#pragma once
// Mesh vertices by key (vertex_key.hpp): the first request for a key fixes
// its id (order of first use, deterministic) and its coordinates; later
// requests with the same key return the same id whatever coordinates they
// pass, so every box that uses a vertex sees one rounding of it.
// With a warp table (set_warps), a Grid key of a grid point the table moved
// names its moved copy, key (Warped, p, F) and the table's coordinates,
// whichever call site asks (grid_vertex in warp.hpp does the same): a square
// centre carried with its corners (warp.hpp) is one vertex on both sides.
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "pqmesh/vec.hpp"
#include "tet3d/points/first_use_index.hpp"
#include "tet3d/points/vertex_key.hpp"
#include "tet3d/warp/warp_table.hpp"

namespace pqmesh::tet3d {

class PointBook {
 public:
  template <class MakeCoordinates>
  int id(const VertexKey& key, MakeCoordinates&& make) {
    const bool plain_grid = key.kind == VertexKind::Grid && key.facet == -1 && key.q == GridPoint{};
    RecentGrid* recent = nullptr;
    if (plain_grid) {
      recent = &recent_[recent_slot(key.p)];
      if (recent->id >= 0 && recent->p == key.p) return recent->id;
    }
    int n;
    if (const Warp* w = warps_ != nullptr && key.kind == VertexKind::Grid ? warps_->find(key.p) : nullptr)
      n = add({VertexKind::Warped, key.p, {}, w->facet}, [&] { return w->at; });
    else
      n = add(key, make);
    if (recent != nullptr) *recent = {key.p, n};
    return n;
  }
  // The table grid keys resolve through (may be null: none). The table must
  // not change while the book uses it (its answers are remembered).
  void set_warps(const WarpTable* warps) {
    warps_ = warps;
    recent_.fill(RecentGrid{});
  }
  const WarpTable* warps() const { return warps_; }
  int find(const VertexKey& key) const { return index_.find(key); }
  const Vec3& point(int id) const { return points_[static_cast<std::size_t>(id)]; }
  const VertexKey& key(int id) const { return index_.key(id); }
  int size() const { return index_.size(); }
  const std::vector<Vec3>& points() const { return points_; }
  // Coordinates and keys by id, moved out when the book is done (no copies
  // at the memory peak of a run); the book is empty afterwards.
  std::vector<Vec3> take_points() {
    std::vector<Vec3> out = std::move(points_);
    points_.clear();
    recent_.fill(RecentGrid{});
    return out;
  }
  std::vector<VertexKey> take_keys() {
    recent_.fill(RecentGrid{});
    return index_.take_keys();
  }

 private:
  template <class MakeCoordinates>
  int add(const VertexKey& key, MakeCoordinates&& make) {
    const auto [n, fresh] = index_.insert(key);
    if (fresh) points_.push_back(make());
    return n;
  }

  // The ids of recently asked plain grid keys (Grid kind, no q, no facet),
  // direct-mapped by grid point: a box's face triangles ask for each ring
  // point two or three times and for a square's centre once per triangle
  // (empty boxes: ~3/4 of the asks), and neighbouring boxes ask for their
  // shared corners in turn. A hit returns the id the full path gave before:
  // ids are never reassigned and the warp table is fixed, so the answer is
  // the same, and no first use is skipped (a hit means the key is in the
  // index), so the order of ids is unchanged.
  struct RecentGrid {
    GridPoint p;
    int id = -1;  // -1: empty
  };
  static constexpr std::size_t kRecentSlots = 64;
  static std::size_t recent_slot(const GridPoint& p) {
    // The top bits of a product depend on all bits of the coordinates (grid
    // coordinates are multiples of large powers of two: their low bits are 0).
    const std::uint64_t x = static_cast<std::uint64_t>(p.f[0]) * 0x9E3779B97F4A7C15ull ^
                            static_cast<std::uint64_t>(p.f[1]) * 0xC2B2AE3D27D4EB4Full ^
                            static_cast<std::uint64_t>(p.f[2]) * 0x165667B19E3779F9ull;
    return static_cast<std::size_t>(x >> 58);  // 6 bits: kRecentSlots
  }
  std::array<RecentGrid, kRecentSlots> recent_{};

  const WarpTable* warps_ = nullptr;
  // Open addressing, ids in order of first use (first_use_index.hpp): the
  // layout never changes the output.
  FirstUseIndex<VertexKey, VertexKeyHash> index_;
  std::vector<Vec3> points_;  // by id
};

// Appends quadrilateral (q0, q1, q2, q3) (cyclic) as two
// triangles cut by the diagonal from its vertex of smallest key. Keys are the
// same in every box, ids are not compared, so two boxes that build the same
// quad (on a shared square) choose the same diagonal whatever corner they
// list first; the triangles keep the quad's orientation.
inline void append_quad_from_smallest_key(const PointBook& book, const std::array<int, 4>& quad,
                                          std::vector<std::array<int, 3>>& out) {
  std::size_t lo = 0;
  for (std::size_t m = 1; m < 4; ++m)
    if (book.key(quad[m]) < book.key(quad[lo])) lo = m;
  const int a = quad[lo], b = quad[(lo + 1) % 4], c = quad[(lo + 2) % 4], d = quad[(lo + 3) % 4];
  out.push_back({a, b, c});
  out.push_back({a, c, d});
}

}  // namespace pqmesh::tet3d
