// build_octree (pqmesh/octree.hpp): OctreeBuilder's tree described leaf by
// leaf for inspection, with each leaf's cone kind (LeafClassifier).
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "mv3d/leaf_kind.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/octree.hpp"

namespace pqmesh {
namespace {

static_assert(kOctreeLeafKinds == mv3d::kLeafKinds);
static_assert(kOctreePhases == static_cast<int>(mv3d::OctPhase::FacetSeparate) + 1);

// A leaf is a duplicate when another node carries its key (thesis §4.1.1).
bool is_duplicate(const OctTree& t, std::int32_t n) {
  const std::int32_t head = t.find(t.key(n));
  return head != n || t.next_same_key(n) >= 0;
}

OctreeLeaf describe_leaf(const mv3d::OctreeBuilder& b, const mv3d::LeafClassifier& classifier, std::int32_t n) {
  const OctTree& t = b.tree();
  const auto box = t.box(n);
  OctreeLeaf leaf;
  for (int k = 0; k < 3; ++k) {
    leaf.lo[static_cast<std::size_t>(k)] = box.lo[k];
    leaf.hi[static_cast<std::size_t>(k)] = box.hi[k];
  }
  leaf.level = t.level(n);
  leaf.component = b.data(n).has_component ? t.component(n) : -1;
  leaf.duplicate = is_duplicate(t, n);
  leaf.protected_box = t.is_protected(n);
  leaf.phase = static_cast<int>(b.phase(n));
  leaf.protected_by = leaf.protected_box ? static_cast<int>(b.protected_by(n)) : 0;
  leaf.vertex_owner = b.data(n).vertex_owner;
  leaf.cone_kind = static_cast<int>(classifier.classify(mv3d::leaf_faces(b, n)).kind);
  return leaf;
}

void copy_counters(const mv3d::OctreeStats& s, OctreeReport& r) {
  r.outside_leaves = s.outside_leaves;
  r.splits_size = s.splits_size;
  r.splits_vertex = s.splits_vertex;
  r.splits_centering = s.splits_centering;
  r.splits_edge = s.splits_edge;
  r.splits_facet = s.splits_facet;
  r.splits_balance = s.splits_balance;
  r.splits_edge_separate = s.splits_edge_separate;
  r.splits_facet_separate = s.splits_facet_separate;
  r.splits_united = s.splits_united;
  r.splits_edge_two_edges = s.splits_edge_two_edges;
  r.duplicates_created = s.duplicates;
  r.vertex_boxes = s.vertex_boxes;
  r.components_split = s.components_split;
  r.components_extended = s.components_extended;
  r.components_adjacency = s.components_adjacency;
  for (int p = 0; p < mv3d::OctreeStats::kPhases; ++p)
    r.phases.push_back({mv3d::OctreeStats::kPhaseNames[p], s.phase_leaves[p], s.phase_seconds[p]});
}

}  // namespace

const char* octree_phase_name(int phase) {
  switch (static_cast<mv3d::OctPhase>(phase)) {
    case mv3d::OctPhase::Root: return "root";
    case mv3d::OctPhase::Vertex: return "vertex";
    case mv3d::OctPhase::Centering: return "centering";
    case mv3d::OctPhase::Edge: return "edge";
    case mv3d::OctPhase::Facet: return "facet";
    case mv3d::OctPhase::Balance: return "balance";
    case mv3d::OctPhase::Size: return "size";
    case mv3d::OctPhase::EdgeSeparate: return "edge-separate";
    case mv3d::OctPhase::FacetSeparate: return "facet-separate";
  }
  return "?";
}

const char* octree_leaf_kind_name(int kind) { return mv3d::to_string(static_cast<mv3d::LeafKind>(kind)); }

OctreeReport build_octree(const Domain3& domain, const OctreeOptions3& options) {
  mv3d::OctreeOptions tree_options;
  tree_options.max_size = options.max_size;
  tree_options.size_field = {options.size_field.points, options.size_field.sizes, options.size_field.lines,
                             options.size_field.path};
  tree_options.generic_grid = options.generic_grid;
  if (options.light) {
    tree_options.extended_margin = 1;
    tree_options.separate = false;
  }
  mv3d::OctreeBuilder builder(domain, std::move(tree_options));
  builder.build();

  OctreeReport report;
  const mv3d::LeafClassifier classifier(builder.domain());
  const std::vector<std::int32_t> leaves = builder.leaves_by_id();
  report.leaves.reserve(leaves.size());
  for (const std::int32_t n : leaves) {
    report.leaves.push_back(describe_leaf(builder, classifier, n));
    report.depth = std::max(report.depth, report.leaves.back().level);
  }
  const auto& root = builder.tree().root();
  report.root_size = root.size;
  report.grid_offset = {root.offset[0], root.offset[1], root.offset[2]};
  copy_counters(builder.stats(), report);
  return report;
}

}  // namespace pqmesh
