#pragma once
// One box job per octree leaf (thesis §4.5). plan_boxes (the aligned grid):
// empty boxes (§4.5.1) and facet boxes (§4.5.4) only; plan_all_kinds (the
// generic grid): every kind.
//
// Rules, per leaf in id order (deterministic):
//   no component (the cube misses P)           -> skipped;
//   flush inside (tet3d/boxes/empty_boxes.hpp) -> empty box: P faces touch the
//                                                 cube only on its boundary and
//                                                 the open cube lies in P;
//   touching outside                           -> skipped: P faces touch the
//                                                 cube only on its boundary and
//                                                 its centre is outside P, so
//                                                 the open cube misses P (the
//                                                 outward perturbation of
//                                                 cube_components.hpp gives
//                                                 such a cube a component of
//                                                 zero volume on a facet);
//   kind EmptyInside                           -> empty box;
//   kind FacetCone                             -> facet box of its facet;
//   any other kind                             -> MeshNotSupported naming the
//                                                 leaf, its kind and its box.
// "Touching only on the boundary" is decided exactly: every facet triangle
// meeting the closed cube lies in a closed half-space bounded by one of the
// cube's planes and missing the open cube (coordinate comparisons with the
// exact box planes), as in is_flush_inside; the centre (an exact grid point)
// is then located with the exact locate().
#include <array>
#include <cstdint>
#include <vector>

#include "mv3d/leaf_kind.hpp"
#include "mv3d/octree_builder.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::mesh3d {

struct BoxPlan {
  std::vector<tet3d::BoxJob> jobs;
  std::array<std::int64_t, mv3d::kLeafKinds> leaves_per_kind{};
  std::int64_t leaves = 0, flush = 0, touching = 0, empty_jobs = 0, facet_jobs = 0;
  std::int64_t edge_jobs = 0, vertex_jobs = 0, two_facet_jobs = 0;
};

// Throws MeshNotSupported (pqmesh/tetmesh.hpp) at the first leaf (in id
// order) of a kind other than empty or facet box.
BoxPlan plan_boxes(const mv3d::OctreeBuilder& builder);

// Every kind (tet3d/boxes/box_jobs.hpp: empty, facet, edge, united vertex boxes,
// two-facet), for octrees on the generic grid. Leaves box_jobs cannot cover
// (its `problems`) throw MeshNotSupported listing the first of them, with
// every such leaf in ids().
BoxPlan plan_all_kinds(const mv3d::OctreeBuilder& builder);

}  // namespace pqmesh::mesh3d
