// The 3D pipeline of pqmesh/tetmesh.hpp: octree, leaf kinds and box jobs,
// box tetrahedra, boundary triangles with facet markers, region attributes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "mesh3d/boundary_faces.hpp"
#include "mesh3d/box_plan.hpp"
#include "mv3d/octree_builder.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/tetmesh.hpp"
#include "quality/tetrahedron_quality_memo.hpp"
#include "tet3d/box_faces.hpp"
#include "tet3d/facet_boxes.hpp"

namespace pqmesh {

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

}  // namespace

const char* tet_leaf_kind_name(int kind) {
  static constexpr const char* kNames[kTetLeafKinds] = {"outside", "empty", "vertex", "edge",
                                                        "facet",   "two-facet", "other"};
  return kind >= 0 && kind < kTetLeafKinds ? kNames[kind] : "?";
}

MeshNotSupported::MeshNotSupported(std::int64_t leaf, std::string kind, const std::string& detail)
    : InvalidInput(ErrorCode::Unsupported, detail, {leaf}), kind_(std::move(kind)) {}

namespace {

// One construction: octree (with or without the separating splits), box
// plan, box tetrahedra, boundary triangles. Throws as tet_mesh does.
TetMeshResult construct(const Domain3& domain, const TetMeshOptions& options, bool separate, Clock::time_point t0) {
  TetMeshResult out;
  TetMeshStats& s = out.stats;
  TetMeshProgress progress;
  auto report = [&](const char* phase) {
    if (!options.progress) return;
    progress.phase = phase;
    progress.seconds = since(t0);
    options.progress(progress);
  };

  report("octree");
  mv3d::OctreeOptions oo;
  oo.max_size = options.max_size;
  oo.size_field.points = options.size_field.points;
  oo.size_field.sizes = options.size_field.sizes;
  oo.size_field.lines = options.size_field.lines;
  oo.size_field.path = options.size_field.path;
  oo.separate = separate;
  s.separated = separate;
  oo.generic_grid = options.generic_grid;
  auto t = Clock::now();
  mv3d::OctreeBuilder builder(domain, std::move(oo));
  builder.build();
  s.seconds_octree = since(t);
  s.root_size = builder.tree().root().size;
  for (int a = 0; a < 3; ++a) s.grid_offset[static_cast<std::size_t>(a)] = builder.tree().root().offset[static_cast<std::size_t>(a)];

  t = Clock::now();
  progress.boxes = builder.tree().leaf_count();
  report("classify");
  // Aligned grid: empty and facet boxes, flush leaves as empty boxes (the
  // grid-aligned models); generic grid: every kind (tet3d/box_jobs.hpp).
  const mesh3d::BoxPlan plan =
      options.generic_grid ? mesh3d::plan_all_kinds(builder) : mesh3d::plan_boxes(builder);
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
  s.seconds_classify = since(t);

  t = Clock::now();
  progress.jobs = static_cast<std::int64_t>(plan.jobs.size());
  report("tetrahedra");
  tet3d::BoxMeshOptions bo;
  bo.warp = options.warp;
  const tet3d::CornerSet corners(builder);
  tet3d::BoxMesh boxes;
  try {
    boxes = tet3d::mesh_boxes(builder.tree(), corners, domain, plan.jobs, bo);
  } catch (const InternalError& e) {
    // Unwarped boxes are valid by construction (every decision exact on the
    // prewarped grid); a failure of the warped run is recorded and the
    // unwarped mesh returned instead, never a silent change of quality.
    if (!bo.warp) throw;
    s.warp_failure = e.what();
    bo.warp = false;
    boxes = tet3d::mesh_boxes(builder.tree(), corners, domain, plan.jobs, bo);
  }
  s.facet_inside = boxes.stats.inside;
  s.facet_on = boxes.stats.on_facet;
  s.facet_beyond = boxes.stats.beyond;
  s.warped = boxes.warped;
  s.warp_rebuilds = boxes.warp_rebuilds;
  s.worst_box_rounds = boxes.worst_box_rounds;
  s.split_squares = boxes.stats.squares_pieces;
  s.seconds_tetrahedra = since(t);
  progress.tetrahedra = static_cast<std::int64_t>(boxes.mesh.tetrahedra.size());

  t = Clock::now();
  report("boundary");
  out.mesh = std::move(boxes.mesh);
  // Vertex keys and job numbers are not needed any more: release them before
  // the boundary tables are built (peak memory).
  std::vector<tet3d::VertexKey>().swap(boxes.keys);
  std::vector<std::int32_t>().swap(boxes.tet_job);
  mesh3d::add_boundary_faces(builder, boxes.tet_leaf, out.mesh);
  s.boundary_faces = static_cast<std::int64_t>(out.mesh.faces.size());
  out.mesh.tetrahedron_markers.assign(out.mesh.tetrahedra.size(), region_attribute(domain));
  s.seconds_boundary = since(t);
  return out;
}

// Largest aspect ratio over the mesh (the memo: the octree's tetrahedra are a
// few thousand shapes repeated).
double max_aspect(const TetMesh3& mesh) {
  TetrahedronQualityMemo memo;
  double worst = 0;
  for (const auto& t : mesh.tetrahedra) {
    const auto& v = mesh.vertices;
    const double a = memo(v[t[0]], v[t[1]], v[t[2]], v[t[3]]).aspect_ratio;
    if (!(a <= worst)) worst = a;  // NaN counts as worst
  }
  return worst;
}

// Why the light construction's mesh is not kept (TetSeparation::Adaptive);
// empty when it is: valid (the checker of pqmesh/check.hpp) and within the
// aspect bound.
std::string light_rejection(const Domain3& domain, TetMeshResult& light) {
  const CheckReport check = check_mesh(light.mesh, domain);
  if (!check.valid()) return "the checker: " + check.to_text().substr(0, check.to_text().find('\n'));
  const double alpha = compute_alpha(domain.plc).radians;
  light.stats.max_aspect = max_aspect(light.mesh);
  if (light.stats.max_aspect * alpha <= kMeasuredAspectAlphaC) return {};
  return "max aspect ratio " + std::to_string(light.stats.max_aspect) + " above C / alpha = " +
         std::to_string(kMeasuredAspectAlphaC / alpha);
}

}  // namespace

TetMeshResult tet_mesh(const Domain3& domain, const TetMeshOptions& options) {
  const auto t0 = Clock::now();
  auto finish = [&](TetMeshResult& r) {
    const TetMeshStats& s = r.stats;
    const std::int64_t jobs = s.empty_jobs + s.facet_jobs + s.edge_jobs + s.vertex_jobs + s.two_facet_jobs;
    const auto tetrahedra = static_cast<std::int64_t>(r.mesh.tetrahedra.size());
    if (options.progress) options.progress(TetMeshProgress{"done", s.leaves, jobs, tetrahedra, since(t0)});
    return std::move(r);
  };
  std::string rejected;
  if (options.separation == TetSeparation::Adaptive) {
    try {
      TetMeshResult light = construct(domain, options, false, t0);
      rejected = light_rejection(domain, light);
      if (rejected.empty()) return finish(light);
    } catch (const MeshNotSupported& e) {
      rejected = e.what();
    } catch (const InternalError& e) {
      rejected = e.what();
    }
  }
  const double light_seconds = since(t0);
  TetMeshResult full = construct(domain, options, true, t0);
  full.stats.light_rejected = rejected;
  full.stats.seconds_light = options.separation == TetSeparation::Adaptive ? light_seconds : 0;
  full.stats.max_aspect = max_aspect(full.mesh);
  return finish(full);
}

}  // namespace pqmesh
