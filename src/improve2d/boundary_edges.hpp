#pragma once
// The boundary pieces of a 2D mesh while the quality pass removes boundary
// Steiner points (quality_pass.hpp, QualityPassOptions::boundary_removable):
// mesh.edges directed with the domain on their left, each vertex with at most
// one piece ending and one starting there. Merging at v replaces a -> v and
// v -> b by a -> b (keeping the first piece's marker); write_back drops the
// merged-away pieces and renumbers the rest.
#include <array>
#include <cstddef>
#include <vector>

#include "pqmesh/mesh.hpp"

namespace pqmesh::detail {

class BoundaryEdges {
 public:
  BoundaryEdges(const TriMesh2& mesh, std::size_t vertex_count)
      : edges_(mesh.edges), alive_(mesh.edges.size(), 1), in_(vertex_count, -1), out_(vertex_count, -1) {
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      out_[std::size_t(edges_[e][0])] = int(e);
      in_[std::size_t(edges_[e][1])] = int(e);
    }
  }

  // The piece ending at v (a -> v) and the one starting there (v -> b), or -1.
  int into(int v) const { return in_[std::size_t(v)]; }
  int from(int v) const { return out_[std::size_t(v)]; }
  const std::array<int, 2>& edge(int e) const { return edges_[std::size_t(e)]; }

  // a -> v -> b becomes a -> b; v is on no piece afterwards.
  void merge_at(int v) {
    const int e_in = in_[std::size_t(v)], e_out = out_[std::size_t(v)];
    const int b = edges_[std::size_t(e_out)][1];
    edges_[std::size_t(e_in)][1] = b;
    alive_[std::size_t(e_out)] = 0;
    in_[std::size_t(b)] = e_in;
    in_[std::size_t(v)] = out_[std::size_t(v)] = -1;
  }

  // The live pieces (and their markers) into mesh, vertices renumbered by id.
  void write_back(const std::vector<int>& id, TriMesh2& mesh) const {
    std::vector<std::array<int, 2>> edges;
    std::vector<int> markers;
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      if (!alive_[e]) continue;
      edges.push_back({id[std::size_t(edges_[e][0])], id[std::size_t(edges_[e][1])]});
      if (!mesh.edge_markers.empty()) markers.push_back(mesh.edge_markers[e]);
    }
    mesh.edges = std::move(edges);
    if (!mesh.edge_markers.empty()) mesh.edge_markers = std::move(markers);
  }

 private:
  std::vector<std::array<int, 2>> edges_;
  std::vector<char> alive_;
  std::vector<int> in_, out_;
};

}  // namespace pqmesh::detail
