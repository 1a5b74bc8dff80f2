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
#include "tet3d/first_use_index.hpp"
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
    return out;
  }
  std::vector<VertexKey> take_keys() { return index_.take_keys(); }

 private:
  template <class MakeCoordinates>
  int add(const VertexKey& key, MakeCoordinates&& make) {
    const auto [n, fresh] = index_.insert(key);
    if (fresh) points_.push_back(make());
    return n;
  }

  const WarpTable* warps_ = nullptr;
  // Open addressing, ids in order of first use (first_use_index.hpp, issue 5
  // item 8): the layout never changes the output.
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
