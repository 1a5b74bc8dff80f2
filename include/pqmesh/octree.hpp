#pragma once
// The octree of thesis §4.1 (Mitchell-Vavasis) on its own, for inspection:
// the leaves the 3D mesher would turn into tetrahedra, with what each one is
// (its level, P-component, phase, cone kind, protection), and the builder's
// counters. `pqmesh octree` writes these leaves as VTK hexahedra.
// docs/algorithm/octree3d.md describes the phases and the leaf kinds.
#include <array>
#include <cstdint>
#include <vector>

#include "pqmesh/domain.hpp"
#include "pqmesh/tetmesh.hpp"

namespace pqmesh {

struct OctreeOptions3 {
  double max_size = 0;       // largest box side anywhere; 0: no limit
  TetSizeField size_field;   // empty: none
  bool generic_grid = false; // true: the generic grid of the 3D mesher; false: the aligned grid
  // true: the octree `pqmesh mesh` tries first (extended boxes of 3 times the
  // side, no separating splits; docs/algorithm/mesh3d.md "Light construction
  // first"); false: the thesis's octree.
  bool light = false;
};

// Phase numbers of OctreeLeaf::phase and protected_by (octree_phase_name).
inline constexpr int kOctreePhases = 9;
const char* octree_phase_name(int phase);  // "root", "vertex", ..., "facet-separate"

// Cone kinds of OctreeLeaf::cone_kind (thesis §4.1.7 Lemma 1; octree_leaf_kind_name).
inline constexpr int kOctreeLeafKinds = 7;
const char* octree_leaf_kind_name(int kind);  // "outside", "empty-inside", ..., "other"

struct OctreeLeaf {
  std::array<double, 3> lo{}, hi{};  // the closed box
  int level = 0;
  int component = -1;     // P-component id of the duplicate, -1 when the cube misses P
  bool duplicate = false; // another leaf carries the same cube (thesis §4.1.1)
  bool protected_box = false;
  int phase = 0;          // the phase that created the leaf
  int protected_by = 0;   // the phase that protected it; 0 when unprotected
  int vertex_owner = -1;  // v when the leaf lies in input vertex v's united box (§4.1.3)
  int cone_kind = 0;
};

// One phase of the build, in build order (OctreeReport::phases).
struct OctreePhaseStats {
  const char* name = "";
  std::int64_t leaves_at_end = 0;
  double seconds = 0;
};

struct OctreeReport {
  std::vector<OctreeLeaf> leaves;  // in node id order
  std::int64_t outside_leaves = 0;
  int depth = 0;                   // deepest leaf level
  double root_size = 0;
  std::array<double, 3> grid_offset{};  // the generic grid's shift (0 when aligned)
  std::int64_t splits_size = 0, splits_vertex = 0, splits_centering = 0, splits_edge = 0, splits_facet = 0;
  std::int64_t splits_balance = 0, splits_edge_separate = 0, splits_facet_separate = 0;
  std::int64_t splits_united = 0;          // light: vertex leaves split so that united boxes do not overlap
  std::int64_t splits_edge_two_edges = 0;  // of splits_edge: the leaf held two edges (of one vertex, §4.1.4)
  std::int64_t duplicates_created = 0, vertex_boxes = 0;
  std::int64_t components_split = 0, components_extended = 0, components_adjacency = 0;
  std::vector<OctreePhaseStats> phases;
};

// Builds the octree of `domain` (all phases of §4.1.7, as the 3D mesher does)
// and describes its leaves. Throws InvalidInput for a bad max_size or size
// field entry (naming the entry and its file line). Cost: the octree build
// plus one cone classification per leaf.
OctreeReport build_octree(const Domain3& domain, const OctreeOptions3& options = {});

}  // namespace pqmesh
