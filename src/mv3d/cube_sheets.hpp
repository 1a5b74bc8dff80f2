#pragma once
// The sheets of P ∩ C (step 3 of the cube_components.cpp outline) and the
// face lists of components, shared by components() and face_bounds().
#include <algorithm>
#include <span>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "pqmesh/domain.hpp"

namespace pqmesh::mv3d::detail {

// Union-find over int elements 0, 1, ... (add() makes the next one); the root
// of a class is its smallest element.
struct UnionFind {
  std::vector<int> p;
  int add() {
    p.push_back(static_cast<int>(p.size()));
    return p.back();
  }
  int find(int x) {
    while (p[static_cast<std::size_t>(x)] != x) x = p[static_cast<std::size_t>(x)] = p[static_cast<std::size_t>(p[static_cast<std::size_t>(x)])];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) p[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

// The index into dom.edges of the P edge ab, or -1 if ab is no P edge.
int edge_index(const Domain3& dom, int a, int b);

// Fills the face lists of every component from the local triangle -> component map.
void fill_faces(const Domain3& dom, const Cube& c, std::span<const int> tris, const std::vector<int>& comp_of,
                CubeComponents& out);

// Step 3: joins the local triangles (union-find elements 0..m-1) of every
// sheet, a component of ∂P ∩ C: two triangles' pieces in C_e share a point iff
// they share a vertex in C or a side meeting C_e (cube_components.cpp outline).
void join_sheets(const Domain3& domain, const Cube& cube, std::span<const int> tris, UnionFind& uf);

}  // namespace pqmesh::mv3d::detail
