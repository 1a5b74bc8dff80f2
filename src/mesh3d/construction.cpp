#include "mesh3d/construction.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "mesh3d/boundary_faces.hpp"
#include "mesh3d/box_plan.hpp"
#include "mv3d/octree_builder.hpp"
#include "tet3d/squares/box_faces.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh::mesh3d {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Region attribute of every tetrahedron. A validated Domain3 is one connected
// polyhedron without internal facets, so it is one region: the attribute of
// the first region point (input order) that lies in P (exact locate, boundary
// counts), else 0. Region points outside P are ignored, as TetGen ignores
// them.
// TetMesh3 markers are integers: the attribute rounded to the nearest one
// (0 when it does not fit an int).
int region_attribute(const Domain3& domain) {
  for (const Region3& r : domain.plc.regions)
    if (locate(domain, r.point) != Location::Outside)
      return std::fabs(r.attribute) < 2147483647.0 ? static_cast<int>(std::lround(r.attribute)) : 0;
  return 0;
}

mv3d::OctreeOptions octree_options(const TetMeshOptions& options, const OctreeVariant& variant) {
  mv3d::OctreeOptions oo;
  oo.max_size = options.max_size;
  oo.size_field.points = options.size_field.points;
  oo.size_field.sizes = options.size_field.sizes;
  oo.size_field.lines = options.size_field.lines;
  oo.size_field.path = options.size_field.path;
  oo.extended_margin = variant.extended_margin;
  oo.separate = variant.separate;
  oo.separate_edges = variant.faces.edges;
  oo.separate_facets = variant.faces.facets;
  oo.generic_grid = options.generic_grid;
  oo.grid_shift = variant.grid_shift;
  return oo;
}

// The box jobs (aligned grid: empty and facet boxes, flush leaves as empty
// boxes; generic grid: every kind, tet3d/boxes/box_jobs.hpp), or nothing when some
// leaf has no job on an octree lighter than the thesis's (c.unsupported).
std::optional<BoxPlan> plan_jobs(const mv3d::OctreeBuilder& builder, const TetMeshOptions& options,
                                 const OctreeVariant& variant, Construction& c) {
  if (!options.generic_grid) return plan_boxes(builder);
  try {
    return plan_all_kinds(builder);
  } catch (const MeshNotSupported& e) {
    if (variant.thesis()) throw;
    c.unsupported = e.what();
    c.review.over_bound = no_faces(builder.domain());
    for (const std::int64_t leaf : e.ids()) flag_leaf_faces(builder, static_cast<std::int32_t>(leaf), c.review.over_bound);
    c.review.over_bound.add_edges_of_facets(builder.domain());
    return std::nullopt;
  }
}

void record_plan(const mv3d::OctreeBuilder& builder, const BoxPlan& plan, TetMeshStats& s) {
  s.leaves = plan.leaves;
  for (int k = 0; k < kTetLeafKinds; ++k)
    s.leaves_per_kind[static_cast<std::size_t>(k)] = plan.leaves_per_kind[static_cast<std::size_t>(k)];
  s.flush_leaves = plan.flush;
  s.touching_leaves = plan.touching;
  s.empty_jobs = plan.empty_jobs;
  s.facet_jobs = plan.facet_jobs;
  s.edge_jobs = plan.edge_jobs;
  s.vertex_jobs = plan.vertex_jobs;
  s.two_facet_jobs = plan.two_facet_jobs;
  for (const std::int32_t n : builder.leaves_by_id()) s.depth = std::max(s.depth, builder.tree().level(n));
}

// The box tetrahedra, warped when options.warp. Unwarped boxes are valid by
// construction (every decision exact on the prewarped grid); a failure of the
// warped run is recorded in s.warp_failure and the unwarped mesh returned
// instead, never a silent change of quality.
// review_stuck_alpha > 0: the run stops after its first warp table when
// review_stuck_corners (with that alpha) drops it (BoxMesh::stuck).
tet3d::BoxMesh box_tetrahedra(const mv3d::OctreeBuilder& builder, const BoxPlan& plan, const TetMeshOptions& options,
                              double review_stuck_alpha, TetMeshStats& s) {
  tet3d::BoxMeshOptions bo;
  bo.warp = options.warp;
  if (review_stuck_alpha > 0)
    bo.stuck_review = [review_stuck_alpha](const tet3d::BoxMesh& m) {
      return review_stuck_corners(m, review_stuck_alpha);
    };
  const tet3d::CornerSet corners(builder);
  tet3d::BoxMesh boxes;
  try {
    boxes = tet3d::mesh_boxes(builder.tree(), corners, builder.domain(), plan.jobs, bo);
  } catch (const InternalError& e) {
    if (!bo.warp) throw;
    s.warp_failure = e.what();
    bo.warp = false;
    bo.stuck_review = nullptr;
    boxes = tet3d::mesh_boxes(builder.tree(), corners, builder.domain(), plan.jobs, bo);
  }
  s.facet_inside = boxes.stats.inside;
  s.facet_on = boxes.stats.on_facet;
  s.facet_beyond = boxes.stats.beyond;
  s.warped = boxes.warped;
  s.warp_rebuilds = boxes.warp_rebuilds;
  s.worst_box_rounds = boxes.worst_box_rounds;
  s.box_runs = boxes.box_runs;
  s.wider_table = boxes.wider_table;
  s.split_squares = boxes.stats.squares_pieces;
  return boxes;
}

}  // namespace

Construction construct(const Domain3& domain, const TetMeshOptions& options, const OctreeVariant& variant,
                       double alpha, Clock::time_point t0, bool review_stuck) {
  Construction c;
  TetMeshStats& s = c.result.stats;
  TetMeshProgress progress;
  auto report = [&](const char* phase) {
    if (!options.progress) return;
    progress.phase = phase;
    progress.seconds = since(t0);
    options.progress(progress);
  };
  s.extended_margin = variant.extended_margin;
  s.grid_shift = variant.grid_shift;
  s.separated = variant.thesis();
  s.separated_faces = variant.faces.count();

  report("octree");
  auto t = Clock::now();
  mv3d::OctreeBuilder builder(domain, octree_options(options, variant));
  builder.build();
  s.seconds_octree = since(t);
  s.root_size = builder.tree().root().size;
  for (std::size_t a = 0; a < 3; ++a) s.grid_offset[a] = builder.tree().root().offset[a];

  t = Clock::now();
  progress.boxes = builder.tree().leaf_count();
  report("classify");
  const std::optional<BoxPlan> plan = plan_jobs(builder, options, variant, c);
  if (!plan) return c;
  record_plan(builder, *plan, s);
  s.seconds_classify = since(t);

  t = Clock::now();
  progress.jobs = static_cast<std::int64_t>(plan->jobs.size());
  report("tetrahedra");
  tet3d::BoxMesh boxes = box_tetrahedra(builder, *plan, options, review_stuck ? alpha : 0.0, s);
  s.seconds_tetrahedra = since(t);
  if (!boxes.stuck.empty()) {
    c.stuck = std::move(boxes.stuck);
    return c;
  }
  progress.tetrahedra = static_cast<std::int64_t>(boxes.mesh.tetrahedra.size());

  t = Clock::now();
  report("boundary");
  TetMesh3& mesh = c.result.mesh;
  mesh = std::move(boxes.mesh);
  // Vertex keys and job numbers are not needed any more: release them before
  // the boundary tables are built (peak memory).
  std::vector<tet3d::VertexKey>().swap(boxes.keys);
  std::vector<std::int32_t>().swap(boxes.tet_job);
  c.face_facets = add_boundary_faces(builder, boxes.tet_leaf, mesh);
  s.boundary_faces = static_cast<std::int64_t>(mesh.faces.size());
  mesh.tetrahedron_markers.assign(mesh.tetrahedra.size(), region_attribute(domain));
  s.seconds_boundary = since(t);
  c.review = review_aspect(builder, boxes.tet_leaf, mesh, alpha);
  s.max_aspect = c.review.max_aspect;
  return c;
}

}  // namespace pqmesh::mesh3d
