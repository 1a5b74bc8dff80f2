#include "mesh3d/box_plan.hpp"

#include <sstream>
#include <string>
#include <utility>

#include "pqmesh/domain.hpp"
#include "pqmesh/tetmesh.hpp"
#include "tet3d/boxes/box_jobs.hpp"
#include "tet3d/boxes/empty_boxes.hpp"
#include "tet3d/points/grid_point.hpp"

namespace pqmesh::mesh3d {

namespace {

std::string describe_leaf(const mv3d::OctreeBuilder& builder, std::int32_t n, const mv3d::LeafFaces& faces) {
  const mv3d::Cube c = builder.cube(n);
  std::ostringstream s;
  s.precision(17);
  s << "box [" << c.lo.x << ", " << c.hi.x << "] x [" << c.lo.y << ", " << c.hi.y << "] x [" << c.lo.z << ", "
    << c.hi.z << "] (level " << builder.tree().level(n) << "); " << mv3d::faces_text(builder.domain(), faces);
  if (faces.vertex_owner >= 0)
    s << "; in the united box of vertex " << faces.vertex_owner + builder.domain().plc.source.first_id;
  return s.str();
}

}  // namespace

BoxPlan plan_boxes(const mv3d::OctreeBuilder& builder) {
  BoxPlan plan;
  const mv3d::LeafClassifier classifier(builder.domain());
  for (const std::int32_t n : builder.leaves_by_id()) {
    ++plan.leaves;
    const mv3d::LeafFaces faces = mv3d::leaf_faces(builder, n);
    const mv3d::LeafClass cls = classifier.classify(faces);
    ++plan.leaves_per_kind[static_cast<std::size_t>(cls.kind)];
    if (cls.kind == mv3d::LeafKind::Outside) continue;
    if (cls.kind == mv3d::LeafKind::EmptyInside) {
      plan.jobs.push_back(tet3d::BoxJob{.leaf = n, .facet = -1, .kind = tet3d::BoxKind::Empty});
      ++plan.empty_jobs;
      continue;
    }
    if (tet3d::facets_on_cube_boundary_only(builder, n)) {
      const Vec3 centre = tet3d::grid_coordinates(builder.tree(), tet3d::key_centre(builder.tree().key(n)));
      if (locate(builder.domain(), centre) == Location::Inside) {
        plan.jobs.push_back(tet3d::BoxJob{.leaf = n, .facet = -1});
        ++plan.flush;
        ++plan.empty_jobs;
      } else {
        ++plan.touching;
      }
      continue;
    }
    if (cls.kind == mv3d::LeafKind::FacetCone) {
      plan.jobs.push_back(tet3d::BoxJob{.leaf = n, .facet = cls.apex});
      ++plan.facet_jobs;
      continue;
    }
    throw MeshNotSupported(n, mv3d::to_string(cls.kind),
                           "leaf " + std::to_string(n) + " (" + describe_leaf(builder, n, faces) + "): kind " +
                               mv3d::to_string(cls.kind) + ", not supported by the 3D mesher");
  }
  return plan;
}

BoxPlan plan_all_kinds(const mv3d::OctreeBuilder& builder) {
  tet3d::BoxJobs bj = tet3d::box_jobs(builder);
  if (!bj.problems.empty())
    throw MeshNotSupported({bj.problem_leaves.begin(), bj.problem_leaves.end()}, "problem",
                           bj.problems.front() + ": not supported by the 3D mesher (" +
                               std::to_string(bj.problems.size()) + " leaves not covered)");
  BoxPlan plan;
  plan.leaves_per_kind = bj.leaves;
  for (const std::int64_t k : bj.leaves) plan.leaves += k;
  for (const tet3d::BoxJob& j : bj.jobs) {
    switch (j.kind) {
      case tet3d::BoxKind::Empty: ++plan.empty_jobs; break;
      case tet3d::BoxKind::Facet: ++plan.facet_jobs; break;
      case tet3d::BoxKind::Edge: ++plan.edge_jobs; break;
      case tet3d::BoxKind::Vertex: ++plan.vertex_jobs; break;
      case tet3d::BoxKind::TwoFacet: ++plan.two_facet_jobs; break;
      case tet3d::BoxKind::FromFacet: (j.facet < 0 ? plan.empty_jobs : plan.facet_jobs)++; break;
    }
  }
  plan.jobs = std::move(bj.jobs);
  return plan;
}

}  // namespace pqmesh::mesh3d
