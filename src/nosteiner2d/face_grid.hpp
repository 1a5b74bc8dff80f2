#pragma once
// A uniform bucket grid over the loop sides and vertices of a Domain2, to
// enumerate only the faces that can lie within distance L(E) of V (the disk
// of Theorem 21's eligibility). A conservative filter: it may return faces
// farther away (the exact tests then reject them) but never misses one, and
// it returns them in the enumeration order of empty_spiral.cpp, so results
// and tie-breaks are those of the plain O(n^2) scan.
#include <array>
#include <vector>

#include "pqmesh/domain.hpp"

namespace pqmesh::detail {

class FaceGrid {
 public:
  explicit FaceGrid(const Domain2& domain);
  // Sides (as indices into sides()) and vertex positions (indices into
  // vertices()) whose bounding boxes meet the square [c - radius, c + radius]^2
  // (widened by one cell), each list in increasing index order.
  void query(Vec2 c, double radius, std::vector<int>& side_ids, std::vector<int>& vertex_ids) const;
  const std::vector<std::array<int, 2>>& sides() const { return sides_; }  // loop sides a -> b, loop order
  const std::vector<int>& vertices() const { return vertices_; }           // vertex ids, loop order

 private:
  std::array<int, 2> cell_of(Vec2 p) const;
  std::vector<std::array<int, 2>> sides_;
  std::vector<int> vertices_;
  Vec2 lo_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> side_cells_, vertex_cells_;
  mutable std::vector<int> stamp_side_, stamp_vertex_;
  mutable int stamp_ = 0;
};

}  // namespace pqmesh::detail
