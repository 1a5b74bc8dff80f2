#pragma once
// Thesis §4.3, second warping pass, for facet boxes: a box vertex v within
// h/16 of the P facet F of a facet box containing it (h: the smallest box
// having v as a vertex, CornerSet::finest_level) is moved by h/16 along F's
// normal, away from F (to the side it is on, decided by exact orient3d).
// Vertices exactly on F's plane are not moved: they are exact boundary points
// already (aligned facets), and the crossings next to them coincide with them.
// The first pass (box edges near P edges) belongs to edge boxes and is not done.
//
// Consistency: the table is complete before any box is meshed, and every box
// resolves its grid points through it, so all boxes sharing v see one moved
// copy, keyed (Warped, v, F). A vertex is left in place and counted as a
// conflict when it is within h/16 of two facets (the thesis's reflex/acute
// special cases, Fig. 4.7, which belong to edge boxes), or when the move would
// change its side of another facet whose facet box uses it: a box face's
// classification (cut_square.hpp) must not depend on which side asks.
#include <cstdint>
#include <span>
#include <unordered_map>

#include "pqmesh/domain.hpp"
#include "tet3d/box_faces.hpp"
#include "tet3d/point_book.hpp"

namespace pqmesh::tet3d {

struct Warp {
  int facet = -1;
  Vec3 at;
};

class WarpTable {
 public:
  const Warp* find(const GridPoint& p) const {
    const auto it = map_.find(p);
    return it == map_.end() ? nullptr : &it->second;
  }
  bool insert(const GridPoint& p, const Warp& w) { return map_.try_emplace(p, w).second; }
  std::size_t size() const { return map_.size(); }
  std::int64_t conflicts = 0;

 private:
  std::unordered_map<GridPoint, Warp, GridPointHash> map_;
};

// (leaf, facet) pairs of facet boxes.
struct FacetLeaf {
  std::int32_t leaf = -1;
  int facet = -1;
};
WarpTable warp_facet_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                              std::span<const FacetLeaf> boxes);

// The mesh vertex of grid point p: its warped copy if the table has one.
int grid_vertex(const GridPoint& p, const OctTree& tree, const WarpTable* warps, PointBook& book);

}  // namespace pqmesh::tet3d
