#include "tet3d/warp.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "tet3d/facet_plane.hpp"

namespace pqmesh::tet3d {

WarpTable warp_facet_vertices(const OctTree& tree, const CornerSet& corners, const Domain3& domain,
                              std::span<const FacetLeaf> boxes) {
  WarpTable table;
  std::map<int, std::unique_ptr<FacetPlane>> planes;
  auto plane_of = [&](int f) -> const FacetPlane& {
    auto it = planes.find(f);
    if (it == planes.end()) it = planes.emplace(f, std::make_unique<FacetPlane>(domain, f)).first;
    return *it->second;
  };
  // Every box vertex on the faces of a facet box, with the facets of the
  // facet boxes it belongs to (in job order, without repeats).
  std::vector<GridPoint> order;
  std::unordered_map<GridPoint, std::vector<int>, GridPointHash> facets_at;
  std::vector<FaceSquare> squares;
  for (const FacetLeaf& fb : boxes) {
    squares.clear();
    for (int axis = 0; axis < 3; ++axis)
      for (const bool upper : {false, true}) face_squares(tree.key(fb.leaf), axis, upper, corners, squares);
    for (const FaceSquare& s : squares)
      for (const GridPoint& p : square_ring(s, corners)) {
        auto [it, fresh] = facets_at.try_emplace(p);
        if (fresh) order.push_back(p);
        if (std::find(it->second.begin(), it->second.end(), fb.facet) == it->second.end()) it->second.push_back(fb.facet);
      }
  }
  for (const GridPoint& p : order) {
    const std::vector<int>& fs = facets_at[p];
    const Vec3 x = grid_coordinates(tree, p);
    const double h = std::ldexp(tree.side(0), -corners.finest_level(p));
    int close = -1, close_count = 0;
    bool on_some = false;
    for (const int f : fs) {
      const FacetPlane& plane = plane_of(f);
      if (plane.side(x) == Sign::Zero) on_some = true;
      if (std::fabs(plane.distance(x)) <= h / 16) {
        ++close_count;
        if (close < 0) close = f;
      }
    }
    // Exactly on a facet: an exact boundary point already, not moved.
    if (close < 0 || on_some) continue;
    const FacetPlane& plane = plane_of(close);
    const double move = (plane.side(x) == Sign::Positive ? 1.0 : -1.0) * h / 16;
    const Vec3 y = x + move * plane.normal();
    // The move must not change the vertex's side of any facet of a facet box
    // using it (else the box faces it shares with other boxes would be
    // classified differently from the two sides). Near two facets (the
    // thesis's special cases of Fig. 4.7 and the acute-edge bisector, which
    // belong to edge boxes) the vertex is left in place.
    bool keeps_sides = close_count == 1;
    for (const int f : fs) keeps_sides = keeps_sides && plane_of(f).side(y) == plane_of(f).side(x);
    if (!keeps_sides) {
      ++table.conflicts;
      continue;
    }
    table.insert(p, Warp{close, y});
  }
  return table;
}

int grid_vertex(const GridPoint& p, const OctTree& tree, const WarpTable* warps, PointBook& book) {
  if (warps != nullptr)
    if (const Warp* w = warps->find(p)) return book.id({VertexKind::Warped, p, {}, w->facet}, [&] { return w->at; });
  return book.id(grid_key(p), [&] { return grid_coordinates(tree, p); });
}

}  // namespace pqmesh::tet3d
