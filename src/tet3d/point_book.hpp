#pragma once
// Mesh vertices by key (vertex_key.hpp): the first request for a key fixes
// its id (order of first use, deterministic) and its coordinates; later
// requests with the same key return the same id whatever coordinates they
// pass, so every box that uses a vertex sees one rounding of it.
#include <unordered_map>
#include <vector>

#include "pqmesh/vec.hpp"
#include "tet3d/vertex_key.hpp"

namespace pqmesh::tet3d {

class PointBook {
 public:
  template <class MakeCoordinates>
  int id(const VertexKey& key, MakeCoordinates&& make) {
    const auto it = ids_.find(key);
    if (it != ids_.end()) return it->second;
    const int n = static_cast<int>(keys_.size());
    ids_.emplace(key, n);
    keys_.push_back(key);
    points_.push_back(make());
    return n;
  }
  int find(const VertexKey& key) const {
    const auto it = ids_.find(key);
    return it == ids_.end() ? -1 : it->second;
  }
  const Vec3& point(int id) const { return points_[static_cast<std::size_t>(id)]; }
  const VertexKey& key(int id) const { return keys_[static_cast<std::size_t>(id)]; }
  int size() const { return static_cast<int>(keys_.size()); }
  const std::vector<Vec3>& points() const { return points_; }

 private:
  std::unordered_map<VertexKey, int, VertexKeyHash> ids_;
  std::vector<VertexKey> keys_;
  std::vector<Vec3> points_;
};

}  // namespace pqmesh::tet3d
