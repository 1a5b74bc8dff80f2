#pragma once
// The octree of the 3D mesher (thesis §4.1, §4.1.7), on the shared Tree<3> of
// src/tree; mirrors quad2d/quadtree_builder.hpp (docs/algorithm/quad2d.md).
//
// Every node carries one component of P ∩ cube (§4.1.1 "Duplicate"): its
// NodeData3 lists the P vertices/edges/facets of that component and one facet
// triangle of it (rep_triangle), which identifies the component inside any
// larger box: a facet triangle meets a convex box in one convex piece, so it
// lies in exactly one component there (cube_components.hpp). A component with
// no triangle is the whole cube (cube ⊂ P); its centre then is a point of it
// off ∂P and is located with components()' marks. Nodes whose extended box
// lies in P and outside every vertex box share the record kInterior. A P vertex
// on a box plane lies in every closed cube sharing it (the outward shift of
// cube_components.hpp), so several leaves may hold it; centering uses one.
//
// Phases (thesis §4.1.7):
//   1. vertex:    split vertex-crowded boxes (§4.1.3);
//   2. centering: split the larger balance-adjacent boxes of every vertex box,
//                 then record the 2x2x2 block around the grid corner nearest
//                 the vertex as its united box (Lemma 1) and protect the leaf
//                 holding the vertex; leaves of the vertex's component inside
//                 the block get vertex_owner (as in 2D,
//                 docs/algorithm/quad2d.md "Phases": no Tree::merge, so the
//                 block still grades towards small boxes);
//                 With extended_margin 1: before centering, the leaves of
//                 vertices whose united blocks would overlap are split
//                 (separate_united_boxes, united_overlap.hpp); part 1
//                 splits only the larger leaves reaching into the block
//                 (not every larger balance-adjacent box), and the
//                 owners are every leaf meeting the block; after the last
//                 phase, leaves that a vertex job would mesh besides their
//                 own are listed (united_clashes);
//   3. edge:      split edge-crowded boxes (§4.1.4);
//   4. edge-separate: split once every unprotected leaf holding a P edge and
//                 its balance-adjacent leaves (§4.1.7 step 6; the set is
//                 collected first, leaves split meanwhile by balancing skipped);
//   5. protect:   protect the edge boxes and their balance-adjacent boxes (§4.1.4);
//   6. facet:     split facet-crowded boxes (§4.1.5);
//   7. facet-separate: the same once-only splits for leaves holding a P facet
//                 (§4.1.7 step 9);
//   8. facet-protect: protect the facet boxes and their balance-adjacent boxes
//                 (§4.1.5 "for the sake of consistent terminology").
// For the separating splits, leaves inside a united vertex box (vertex_owner
// >= 0) count as protected (pieces of the protected vertex box, §4.1.3).
// Balance (§4.1.1) between balance-adjacent boxes is restored after every split
// (Tree::balance; protected boxes are never split).
// Deviations (documented at edge_crowded / facet_crowded): extended boxes are not
// cut by protected boxes; instead a face sharing a vertex with the apex
// interferes only if it meets P ∧ b itself (the 2D edge rule), or, in the
// edge phase, a facet lies in a leaf that step 5 above would protect with b and
// that would be of no kind of leaf_kind.hpp (neighbour_would_be_of_no_kind).
// Cost: dominated by components() (exact, double filters before GMP): one per
// child meeting ∂P per split, one per extended box that an undecided
// crowding test (face_bounds' sheet and all-triangle bounds disagree,
// octree_builder.cpp extended_interferes) or an undecided balance-adjacency
// query needs (cached per node), and one per
// undecided balance-adjacency query involving a box inside P (balance_adjacent
// first tries the shared-triangle and whole-cube rules, octree_builder.cpp). Each looks only at
// the candidate triangles handed down the tree (cube_tris, ex_tris) and
// starts from the status of corner 0 derived from the parent's, so a box
// costs O(candidates), independent of the number of facet triangles.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "mv3d/cube_components.hpp"
#include "mv3d/facet_pair_edges.hpp"
#include "pqmesh/domain.hpp"
#include "tree/tree.hpp"

namespace pqmesh::mv3d {

// Values are written to .vtu cell data (cmd_octree.cpp): append, never renumber.
enum class OctPhase : std::uint8_t { Root, Vertex, Centering, Edge, Facet, Balance, Size, EdgeSeparate, FacetSeparate };

// The user size function of thesis §1.1 ("the largest desired box containing
// that point"), as in 2D (quad2d/size_function.hpp): f(x) = min(max_size,
// min_i sizes[i] + |x - points[i]|), 1-Lipschitz, so the requested octree is
// graded. Phase 0 splits a box (meeting P) while its side exceeds the minimum
// of f over it.
struct SizeField3 {
  std::vector<Vec3> points;
  std::vector<double> sizes;
  std::vector<int> lines;  // 1-based file line of each point (0: not from a file), for errors
  std::string path;
};
struct OctreeOptions {
  double max_size = 0;    // largest box side anywhere; 0: no cap
  SizeField3 size_field;  // empty: none
  // The once-only separating splits of §4.1.7 steps 6 and 9 (every edge /
  // facet box and its balance-adjacent boxes split once before protection).
  // With them every leaf is one of the thesis's kinds (without them a
  // protected box may hold three facets of a vertex outside it); they cost
  // 10 to 25 times the tetrahedra (docs/algorithm/octree3d.md). The 3D
  // mesher tries the octree without them first (docs/algorithm/mesh3d.md).
  bool separate = true;
  // With separate: when not empty, only leaves holding a P edge (facet) whose
  // flag is set start a separation set, so the splits stay near those faces
  // (flags indexed by Domain3 edge / facet id; sizes equal to the counts).
  // Empty: every edge and facet, the thesis's rule.
  std::vector<char> separate_edges, separate_facets;
  // ex(b) reaches this many box sides beyond b on every side (§4.1.1: 2, the
  // cube of 5 times the side). 1 (3 times the side) declares fewer boxes
  // crowded: a lighter octree that the 3D mesher tries first
  // (docs/algorithm/mesh3d.md "Light construction first"). 1 or 2.
  int extended_margin = 2;
  // Generic grid (tree/root_cube.hpp choose_generic_root_cube;
  // docs/algorithm/octree3d.md): every box plane is shifted by a fixed offset
  // so that no input vertex coordinate lies on a box plane of any level the
  // tree may use. Off by default (the aligned grid; the existing octree tests
  // use it).
  bool generic_grid = false;
  // With generic_grid: which offset (choose_generic_root_cube's `shift`; 0
  // the default). Another shift moves every box plane relative to the input.
  int grid_shift = 0;
};

struct NodeData3 {
  std::vector<int> cube_tris;                // facet triangles meeting the closed cube (all components)
  std::vector<int> ex_tris;                  // facet triangles meeting ex(b); candidates for the children
  std::vector<int> vertices, edges, facets;  // P faces of P ∧ b
  int rep_triangle = -1;                     // a facet triangle meeting P ∧ b, -1 if P ∧ b is the whole cube
  bool has_component = false;                // false: the cube misses P
  bool cube_single = false;                  // P ∩ cube has exactly one component (no duplicates of this cube)
  int vertex_owner = -1;                     // v if this leaf lies in v's united box (§4.1.3)
  // Corner 0 of the shifted cube / of the shifted ex(b) lies in P
  // (cube_components.hpp): with cube_tris / ex_tris, all that components()
  // needs, so no call looks at every facet triangle.
  bool cube_corner0_in = false, ex_corner0_in = false;
};

struct OctreeStats {
  std::int64_t splits_size = 0;
  std::int64_t splits_vertex = 0, splits_centering = 0, splits_edge = 0, splits_facet = 0, splits_balance = 0;
  std::int64_t splits_edge_separate = 0, splits_facet_separate = 0;  // §4.1.7 steps 6 and 9
  std::int64_t splits_united = 0;  // margin 1: vertex leaves split so that united boxes do not overlap
  // Of splits_edge: the leaf held two edges (of one P vertex outside it; the
  // rest were crowded by faces of the extended box).
  std::int64_t splits_edge_two_edges = 0;
  std::int64_t duplicates = 0;
  std::int64_t leaves = 0, outside_leaves = 0, vertex_boxes = 0;
  // components() calls (the dominant cost): for children and parents at a
  // split, for cached extended boxes, for uncached balance-adjacency queries.
  std::int64_t components_split = 0, components_extended = 0, components_adjacency = 0;
  // Per phase of build(), in the order of kPhaseNames: wall seconds, and
  // leaves (all duplicates counted) when it ends.
  static constexpr int kPhases = 9;
  static constexpr const char* kPhaseNames[kPhases] = {
      "size", "vertex", "centering", "edge", "edge-separate", "protect", "facet", "facet-separate", "facet-protect"};
  double phase_seconds[kPhases] = {};
  std::int64_t phase_leaves[kPhases] = {};
};

// The faces of P ∧ ex(b) (§4.1.1 "Extended Box").
struct ExtendedFaces3 {
  std::vector<int> vertices, edges, facets;
};

class OctreeBuilder {
 public:
  // Throws InvalidInput for a negative or non-finite max_size and for a size
  // field entry with a non-finite point or a size that is not positive and
  // finite (naming the entry and its file line).
  explicit OctreeBuilder(const Domain3& domain, OctreeOptions options = {});
  void build();

  const OctTree& tree() const { return tree_; }
  const Domain3& domain() const { return domain_; }
  const OctreeStats& stats() const { return stats_; }
  const NodeData3& data(std::int32_t node) const { return data_[static_cast<std::size_t>(tree_.payload(node))]; }
  Cube cube(std::int32_t node) const;
  Cube ex_cube(std::int32_t node) const;  // ex(b), thesis §4.1.1
  std::vector<std::int32_t> leaves_by_id() const;
  // The united box of vertex v (2x2x2 block, §4.1.3); lo > hi if v was not centred.
  const Cube& vertex_box(int v) const { return vertex_box_[static_cast<std::size_t>(v)]; }
  // Leaves that two box jobs would mesh, which the box plan refuses
  // (tet3d/boxes/box_jobs.hpp): a piece of the united boxes of two vertices
  // (first, second), or, on the margin-1 octree, a leaf that meets first's
  // united box B and lies in first's component of P ∩ B (or reaches out of
  // B) without being a piece of B (second = -1; the vertex job meshes that
  // component). Margin 1 separates the united boxes (united_overlap.hpp)
  // but not the rest; the thesis's extended boxes leave neither kind.
  struct UnitedClash {
    std::int32_t leaf = -1;
    int first = -1, second = -1;
  };
  const std::vector<UnitedClash>& united_clashes() const { return united_clashes_; }
  // Thesis §4.1.1: balance-adjacency of neighbours big, small (h(big) >= h(small));
  // small must lie in ex(big) (a neighbour, or a box of big's united vertex box).
  bool balance_adjacent(std::int32_t big, std::int32_t small) const;
  ExtendedFaces3 extended_faces(std::int32_t node) const;
  // The phase whose split (or balancing) created the node (Root for the root).
  OctPhase phase(std::int32_t node) const;
  // The step that protected the node: Centering (vertex box), Edge (§4.1.4
  // edge-box protection), Facet (§4.1.5 facet-box protection); Root if unprotected.
  OctPhase protected_by(std::int32_t node) const;

 private:
  static constexpr std::int32_t kInterior = 1;
  NodeData3& own_data(std::int32_t node);
  void init_root();
  void assign_children(std::int32_t parent, std::int32_t first_child);
  std::int32_t split_and_balance(std::int32_t node, OctPhase which);
  void balance(std::span<const std::int32_t> seeds);
  // Component of `ex` holding P ∧ node (ex a box containing the node's cube).
  int component_in(std::int32_t node, const CubeComponents& ex) const;
  CubeComponents extended_components(std::int32_t node, std::span<const Vec3> marks) const;
  // Components of P ∩ ex(node), computed once per node (the node's cube never
  // changes); the centre of the node is mark 0 when P ∧ node is the whole cube.
  const CubeComponents& cached_extended(std::int32_t node) const;

  // Does some face of P ∧ ex(node) interfere, by `rule` (monotone: a face set
  // holding an interfering face makes every superset interfere)? Decided by
  // face_bounds (cube_components.hpp) when its bounds agree, else on
  // extended_faces.
  template <class Rule>
  bool extended_interferes(std::int32_t node, const Rule& rule) const;
  bool size_crowded(std::int32_t node) const;
  double size_over(const Cube& c) const;  // min of the size function over the closed cube
  bool vertex_crowded(std::int32_t node) const;
  bool edge_crowded(std::int32_t node) const;
  bool neighbour_would_be_of_no_kind(std::int32_t node, const DomainEdge& e) const;
  bool facet_crowded(std::int32_t node) const;
  void run_phase(OctPhase which, bool (OctreeBuilder::*crowded)(std::int32_t) const);
  void center_vertices();
  std::vector<std::int32_t> vertex_leaves() const;  // per P vertex: the leaf centering uses, -1 if none
  unsigned united_below(std::int32_t b, int v) const;  // bit a: v's united box extends below leaf b along a
  void separate_united_boxes();
  std::vector<std::int32_t> leaves_in_block(std::int32_t b, int v) const;  // leaves meeting v's united box
  void find_united_intruders();
  // Leaves meeting P that hold a P edge (Edge) or a P facet (Facet), outside
  // every protected box, with their balance-adjacent unprotected leaves.
  std::vector<std::int32_t> separation_set(bool facets) const;
  void separate(OctPhase which);    // §4.1.7 steps 6 and 9
  void protect_boxes(bool facets);  // §4.1.4 / §4.1.5 protection
  void protect(std::int32_t node, OctPhase step);
  bool shielded(std::int32_t node) const;  // protected, or a piece of a united vertex box
  void record_phase(std::int32_t node);
  bool facet_has_vertex(int facet, int v) const;

  const Domain3& domain_;
  OctreeOptions options_;
  OctTree tree_;
  mutable OctreeStats stats_;  // mutable: const queries count their components() calls
  std::vector<NodeData3> data_;
  std::vector<Cube> vertex_box_;
  std::vector<UnitedClash> united_clashes_;
  std::vector<std::vector<int>> facet_vertices_;  // sorted vertex ids of each facet (all loops)
  FacetPairEdges facet_pair_edges_;
  mutable std::vector<std::unique_ptr<CubeComponents>> ex_cache_;  // per node id, see cached_extended
  std::vector<OctPhase> phase_;                                    // per node id
  std::vector<OctPhase> protected_by_;                             // per node id, see protected_by
  OctPhase current_phase_ = OctPhase::Root;
};

}  // namespace pqmesh::mv3d
