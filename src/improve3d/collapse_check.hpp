#pragma once
// One edge collapse: the rules of improve.hpp checked in order of cost
// (cheapest first), then the change applied to the CollapseMesh.
//
// Notation: u is deleted, v kept. The star of u splits into the tetrahedra
// holding v ("dying": they vanish) and the others ("moving": u becomes v);
// the tetrahedra of v not holding u stay as they are ("resting"). The ring is
// the set of vertices of the dying tetrahedra other than u and v, that is the
// vertices of Lk(uv). Boundary triangles split the same way.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "improve3d/collapse_mesh.hpp"
#include "improve3d/size_bound.hpp"
#include "improve3d/vertex_classes.hpp"
#include "quality/tetrahedron_quality_memo.hpp"

namespace pqmesh::improve3d::detail {

struct QualityLimits {
  double cap = 0;     // ImproveOptions::aspect_cap
  double target = 0;  // ImproveOptions::target_aspect
  double min_dihedral = 0;  // ImproveOptions::min_dihedral (degrees)
};

// Why collapses were refused (counts for tuning: Collapser::refusals).
enum class Refusal : int { Class, NoEdge, Region, Link, Boundary, Size, Orientation, Quality };
inline constexpr int kRefusalKinds = 8;

class Collapser {
 public:
  Collapser(CollapseMesh& mesh, const VertexClasses& classes, const SizeBound& size, QualityLimits limits,
            TetrahedronQualityMemo& memo);

  // Collapses u onto v when every rule holds; returns whether it did.
  bool try_collapse(int u, int v);
  // The last refusal holds for the edge either way round (the link
  // condition is symmetric in u and v; a missing edge is missing both ways).
  // Forgets the stars gathered for the last edge tried: call after the mesh
  // changed by anything but try_collapse (smoothing, flips).
  void forget() {
    for (Gathered* g : {&u_tets_, &v_tets_, &u_faces_, &v_faces_}) g->owner = -1;
  }
  bool refused_both_ways() const { return last_refusal_ == Refusal::NoEdge || last_refusal_ == Refusal::Link; }
  // After a collapse: the vertices whose stars changed (the neighbours of u,
  // v among them) and the vertices that became neighbours of v.
  const std::vector<int>& changed() const { return near_u_list_; }
  const std::vector<int>& new_neighbours() const { return new_neighbours_; }
  const std::array<std::int64_t, kRefusalKinds>& refusals() const { return refusals_; }

 private:
  bool refuse(Refusal why);
  struct Gathered {
    int owner = -1;  // the vertex whose elements `list` holds; -1: none
    std::vector<int> list;
  };
  void gather_tets(Gathered& g, int x);
  void gather_faces(Gathered& g, int x);
  bool class_allows() const;
  bool split_u();
  void split_v();
  void split_faces();
  bool one_region() const;
  bool link_condition();
  bool vertex_links_agree();
  bool edge_links_agree() const;
  bool ring_edge_or_outside_lk_u(int a, int b) const;
  bool boundary_allows();
  bool virtual_vertex_links_agree();
  bool edge_vertex_moves_along_edge() const;
  bool no_duplicate_face() const;
  bool within_size() const;
  bool new_edges_within_uniform_size() const;
  bool is_new_neighbour(int x) const;
  void list_new_neighbours();
  bool moved_positive() const;
  bool quality_allows();
  std::array<int, 4> moved(int t) const;
  bool mark(std::vector<std::uint32_t>& marks, int x) const;
  bool marked(const std::vector<std::uint32_t>& marks, int x) const;

  CollapseMesh& mesh_;
  const VertexClasses& classes_;
  const SizeBound& size_;
  QualityLimits limits_;
  TetrahedronQualityMemo& memo_;

  int u_ = -1, v_ = -1;
  Gathered u_tets_, v_tets_, u_faces_, v_faces_;
  std::vector<int> dying_, moving_, resting_;
  std::vector<int> dying_faces_, moving_faces_, resting_faces_;
  std::vector<int> near_u_list_, new_neighbours_;
  std::vector<std::pair<int, int>> ring_edges_;  // the edges of Lk(uv), (smaller, larger)
  std::vector<double> new_aspect_, new_dihedral_;
  // Marks equal to stamp_ are set in the current try: neighbours of u, ring,
  // neighbours of v, boundary neighbours of u, third vertices of the dying
  // boundary triangles.
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> near_u_, ring_, near_v_, boundary_near_u_, boundary_ring_;
  std::array<std::int64_t, kRefusalKinds> refusals_{};
  Refusal last_refusal_ = Refusal::Class;
};

}  // namespace pqmesh::improve3d::detail
