#pragma once
// The quadtree of the 2D mesher: thesis §4.1 in two dimensions (the "two
// dimensional analog of Chapter 4", §5.5.1), on the shared Tree<2> of src/tree.
//
// Every node of the tree carries one component of P ∩ cube (thesis §4.1.1
// "Duplicate"): the tree's component() is the index of that component among
// components(domain, square) (components2d.hpp), and the node's NodeData lists
// its P faces. A cube meeting P in k > 1 components has k nodes, one per
// component (duplicates); a cube missing P is a leaf without a component.
//
// Phases (docs/algorithm/quad2d.md walks them with the thesis sections):
//   0. size:      split while the side exceeds the user size function (§1.1);
//   1. vertex:    split vertex-crowded boxes (§4.1.3);
//   2. centering: split the larger balance-adjacent boxes of every vertex box,
//                 then record the 2x2 block around the vertex as its protected
//                 box (§4.1.3, Fig. 4.3, Lemma 1);
//   3. edge:      split edge-crowded boxes (the 2D analog of the facet phase,
//                 §4.1.5), extended boxes ignoring what lies in vertex boxes;
//   4. protect:   (optional, QuadMeshOptions::protect_edges) split every
//                 unprotected box on an edge once (§4.1.4-4.1.5 "protecting"),
//                 then protect the boxes on edges.
// The balance condition (§4.1.1) on balance-adjacent boxes is restored after
// every split.
#include <cstdint>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/quadmesh.hpp"
#include "quad2d/components2d.hpp"
#include "quad2d/segment_box.hpp"
#include "quad2d/size_function.hpp"
#include "tree/tree.hpp"

namespace pqmesh::quad2d {

// The crowding phases run by run_phase (the others have their own functions).
enum class Phase : std::uint8_t { Size, Vertex, Edge };

struct NodeData {
  std::vector<LoopEdge> square_edges;  // P edges meeting the closed square (all components; Euclidean)
  std::vector<LoopEdge> ex_edges;      // P edges meeting ex(b) (Euclidean); candidates for the children
  std::vector<int> vertices;           // P vertices of P ∧ b
  std::vector<int> segments;           // input segment ids of the P edges meeting P ∧ b
  bool has_component = false;          // false: the cube does not meet P
  int vertex_owner = -1;               // v if this leaf lies in v's united box (§4.1.3)
};

// The faces of P ∧ ex(b) (thesis §4.1.1 "Extended Box").
struct ExtendedFaces {
  std::vector<int> vertices;
  std::vector<int> segments;
};

class QuadtreeBuilder {
 public:
  QuadtreeBuilder(const Domain2& domain, const SizeFunction2& size, bool protect_edges, QuadMeshStats& stats);
  void build();

  const QuadTree& tree() const { return tree_; }
  const Domain2& domain() const { return domain_; }
  const NodeData& data(std::int32_t node) const { return data_[static_cast<std::size_t>(tree_.payload(node))]; }
  Square square(std::int32_t node) const;
  // The leaves in id (creation) order: deterministic, and much cheaper than
  // Tree::leaves()'s z-order sort when the order does not matter.
  std::vector<std::int32_t> leaves_by_id() const;
  // The united box of input vertex v (the 2x2 block of §4.1.3), as a closed
  // rectangle; degenerate (lo > hi) for a vertex on no segment.
  const Rect& vertex_box(int v) const { return vertex_box_[static_cast<std::size_t>(v)]; }
  // Lemma 1's clearance: no mesh vertex other than v within this distance of v
  // (half the side of the leaf that held v when it was centred).
  double vertex_clearance(int v) const { return 0.25 * (vertex_box(v).hi.x - vertex_box(v).lo.x); }
  // The segment id -> loop edge table.
  LoopEdge loop_edge(int segment) const { return segment_edge_[static_cast<std::size_t>(segment)]; }

  // Components of P ∩ square(node), computed from the node's candidate lists.
  SquareComponents components_of(std::int32_t node) const;

 private:
  // Nodes whose square lies inside P, away from vertex boxes, all share the
  // record kInterior (they have no faces to list): the tree's bulk costs no
  // per-node lists. own_data() gives a node its own record before a change.
  static constexpr std::int32_t kInterior = 1;
  NodeData& own_data(std::int32_t node);
  // The leaves with a record of their own (not kInterior), in id order: among
  // them every leaf that holds a vertex, meets an edge, lies in a vertex box
  // or misses P (a kInterior leaf is inside P with no faces).
  std::vector<std::int32_t> recorded_leaves() const;
  void init_root();
  // Thesis §4.1.1: "Whenever a box is split, we immediately determine whether any
  // of its children contains more than one component of P, and if so, we make
  // duplicates of the child box." Children get the components of P ∩ child that
  // lie in P ∧ parent.
  void assign_children(std::int32_t parent, std::int32_t first_child);
  std::int32_t split(std::int32_t node);
  void balance(std::span<const std::int32_t> seeds);
  // Thesis §4.1.1: "If we split a box, we immediately split other boxes to
  // maintain ... the balance condition." Returns the first new node id (every
  // node created by the split and the balancing has an id >= it).
  std::int32_t split_and_balance(std::int32_t node);
  bool balance_adjacent(std::int32_t big, std::int32_t small) const;
  ExtendedFaces extended_faces(std::int32_t node) const;
  int extended_component(std::int32_t node, const SquareComponents& ex) const;

  bool size_crowded(std::int32_t node) const;
  bool vertex_crowded(std::int32_t node) const;
  bool edge_crowded(std::int32_t node) const;

  void reserve_for_size_phase();
  void run_phase(Phase phase, bool (QuadtreeBuilder::*crowded)(std::int32_t) const);
  void center_vertices();
  void protect_edges();

  const Domain2& domain_;
  const SizeFunction2& size_;
  QuadMeshStats& stats_;
  QuadTree tree_;
  std::vector<NodeData> data_;
  std::vector<std::int32_t> record_node_;  // per record of data_: its node (-1 for kInterior)
  std::vector<Rect> vertex_box_;
  std::vector<LoopEdge> segment_edge_;
  bool protect_edges_ = false;
};

}  // namespace pqmesh::quad2d
