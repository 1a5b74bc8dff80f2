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
  int find(const VertexKey& key) const { return index_.find(key); }
  const Vec3& point(int id) const { return points_[static_cast<std::size_t>(id)]; }
  const VertexKey& key(int id) const { return index_.key(id); }
  int size() const { return index_.size(); }
  const std::vector<Vec3>& points() const { return points_; }

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

}  // namespace pqmesh::tet3d
