#pragma once
// What smoothing and flips changed, for the collapse passes of the next round
// (improve.cpp): whether an edge collapses depends only on the stars of its two
// ends (their tetrahedra, boundary triangles, the positions of the vertices in
// them) and the fixed vertex classes, so a refused edge needs a new try only
// when one of its ends' stars changed, and an edge made by a flip needs its
// first try.
//
// StarChanges::take() before the mesh is changed records the positions and
// the first vertex of every tetrahedron; since() afterwards lists
//   - the changed vertices: every moved vertex and its neighbours, every
//     vertex of a tetrahedron made or deleted since take();
//   - the new edges: those of the tetrahedra made since take() (ids at or
//     above the count at take(): CollapseMesh appends new tetrahedra).
// A deleted tetrahedron keeps its id and its vertices but the first (-1), and a
// new one gets a new id (collapse_mesh.hpp), so the first vertices recorded
// name every tetrahedron deleted since take().
// Cost: O(vertices + tetrahedra) per call, plus the stars of the moved
// vertices; memory: a point per vertex and an id per tetrahedron.
#include <cstdint>
#include <utility>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::improve3d::detail {

class StarChanges {
 public:
  void take(const CollapseMesh& mesh);
  // Fills vertices (each once, increasing) and edges (each once as (smaller, larger), sorted).
  void since(CollapseMesh& mesh, std::vector<int>& vertices, std::vector<std::pair<int, int>>& edges);

 private:
  std::vector<Vec3> points_;
  std::vector<int> first_;  // first vertex of every tetrahedron at take(); -1: dead
};

}  // namespace pqmesh::improve3d::detail
