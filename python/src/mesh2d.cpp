// The two 2D meshers as `pqmesh mesh` runs them (cmd_mesh.cpp and, with
// --no-boundary-steiner, cmd_mesh_nosteiner.cpp), with the GIL released; the
// figures of the CLI's summary become attributes of the returned TriMesh.
#include <memory>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/nosteiner.hpp"
#include "pqmesh/quadmesh.hpp"
#include "pqmesh/quadmesh_bound.hpp"
#include "pqmesh/quality.hpp"
#include "timed.hpp"

namespace pqmesh::python {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

py::dict quad_stats(const QuadMeshStats& s) {
  return py::dict(py::arg("leaves") = s.leaves, py::arg("duplicates") = s.duplicates,
                  py::arg("outside_leaves") = s.outside_leaves, py::arg("splits_size") = s.splits_size,
                  py::arg("splits_vertex") = s.splits_vertex, py::arg("splits_edge") = s.splits_edge,
                  py::arg("splits_balance") = s.splits_balance, py::arg("splits_centering") = s.splits_centering,
                  py::arg("splits_protection") = s.splits_protection, py::arg("vertex_boxes") = s.vertex_boxes,
                  py::arg("centered") = s.centered, py::arg("warped") = s.warped,
                  py::arg("edge_points") = s.edge_points, py::arg("refine_points") = s.refine_points,
                  py::arg("refine_target_reached") = s.refine_target_reached,
                  py::arg("refined_input") = s.refined_input,
                  py::arg("refined_input_min_angle") = s.refined_input_min_angle,
                  py::arg("refined_input_triangles") = s.refined_input_triangles, py::arg("improved") = s.improved,
                  py::arg("constructed_triangles") = s.constructed_triangles,
                  py::arg("constructed_min_angle") = s.constructed_min_angle,
                  py::arg("improve_removed") = s.improve_removed, py::arg("improve_moved") = s.improve_moved,
                  py::arg("improve_flips") = s.improve_flips, py::arg("improve_target") = s.improve_target_degrees);
}

py::object run_mesh_polygon(std::shared_ptr<Domain2> domain, double max_size, py::object size_field,
                            double refine_angle, bool protect_edges, bool quadtree, bool improve) {
  QuadMeshOptions options;
  options.max_size = max_size;
  options.refine_angle_degrees = refine_angle;
  options.protect_edges = protect_edges;
  options.quadtree = quadtree;
  options.improve = improve;
  // A size-field file (read_size_field2: "x y size" lines) or a pair (points (K, 2), sizes (K,)).
  if (!size_field.is_none()) options.size_field = to_size_field(size_field, read_size_field2, to_points2);
  QuadMeshResult result;
  AlphaResult alpha;
  QualityReport quality;
  double seconds = 0;
  {
    py::gil_scoped_release release;
    seconds = seconds_of([&] { result = mesh_polygon(*domain, options); });
    alpha = compute_alpha(domain->pslg.vertices, domain->loops);
    quality = quality_report(result.mesh);
  }
  const QuadMeshStats& s = result.stats;
  py::object mesh = py::cast(std::make_shared<TriMesh2>(std::move(result.mesh)));
  mesh.attr("domain") = domain;
  mesh.attr("alpha") = alpha.degrees();
  mesh.attr("angle_bound") = quad_mesh_angle_bound(alpha.degrees(), refine_angle);
  mesh.attr("min_angle") = quality.min_angle.min;
  mesh.attr("max_angle") = quality.max_angle.max;
  mesh.attr("max_aspect_ratio") = quality.aspect_ratio.max;
  mesh.attr("stats") = quad_stats(s);
  mesh.attr("seconds") = py::dict(py::arg("tree") = s.seconds_tree, py::arg("points") = s.seconds_points,
                                  py::arg("triangulate") = s.seconds_triangulate,
                                  py::arg("improve") = s.seconds_improve, py::arg("mesh") = seconds);
  return mesh;
}

// As cmd_mesh_nosteiner.cpp: min_angle > 0 (--min-angle) refines towards it
// alone and reports it; keep_better_cdt = false (--pipeline) and thesis_fans
// keep the thesis pipeline's mesh (no refined candidate).
py::object run_no_steiner(std::shared_ptr<Domain2> domain, double refine_angle, bool keep_better_cdt, bool thesis_fans,
                          bool quality_pass, double min_angle) {
  NoSteinerOptions options;
  options.r_mesh.refine_angle_degrees = refine_angle;
  if (min_angle > 0) {
    options.min_angle_target = min_angle;
    options.refine_targets = {min_angle};
  }
  options.keep_better_cdt = keep_better_cdt;
  options.thesis_fans = thesis_fans;
  if (!keep_better_cdt || thesis_fans) options.refine_targets.clear();
  options.quality_pass = quality_pass;
  NoSteinerResult result;
  QualityReport quality;
  {
    py::gil_scoped_release release;
    result = triangulate_without_boundary_steiner(*domain, options);
    quality = quality_report(result.mesh);
  }
  const NoSteinerStats& s = result.stats;
  py::object mesh = py::cast(std::make_shared<TriMesh2>(std::move(result.mesh)));
  mesh.attr("domain") = domain;
  mesh.attr("g") = s.g * kDegrees;
  mesh.attr("upper_bound") = s.upper_bound * kDegrees;
  mesh.attr("min_angle") = quality.min_angle.min;
  mesh.attr("max_angle") = quality.max_angle.max;
  mesh.attr("max_aspect_ratio") = quality.aspect_ratio.max;
  mesh.attr("cdt_min_angle") = s.cdt_min_angle * kDegrees;
  mesh.attr("path") = to_string(s.path);
  mesh.attr("fallback_reason") = s.fallback_reason;
  mesh.attr("target") = s.target;
  mesh.attr("target_reached") = s.target_reached;
  mesh.attr("stats") = py::dict(
      py::arg("pipeline_path") = to_string(s.pipeline_path), py::arg("pipeline_min_angle") = s.pipeline_min_angle * kDegrees,
      py::arg("construction_min_angle") = s.construction_min_angle * kDegrees, py::arg("ratio") = s.ratio,
      py::arg("wedge_triangles") = s.wedge_triangles, py::arg("between_triangles") = s.between_triangles,
      py::arg("r_triangles") = s.r_triangles, py::arg("cdt_triangles") = s.cdt_triangles,
      py::arg("pass_flips") = s.pass_flips, py::arg("pass_removals") = s.pass_removals,
      py::arg("pass_moves") = s.pass_moves, py::arg("pass_cavities") = s.pass_cavities);
  mesh.attr("seconds") = py::dict(py::arg("bound") = s.seconds_bound, py::arg("q") = s.seconds_q,
                                  py::arg("r") = s.seconds_r, py::arg("between") = s.seconds_between,
                                  py::arg("pass") = s.seconds_pass, py::arg("verify") = s.seconds_verify,
                                  py::arg("cdt") = s.seconds_cdt, py::arg("mesh") = s.seconds_total);
  return mesh;
}

}  // namespace

void bind_mesh2d(py::module_& m) {
  m.def("mesh_polygon", &run_mesh_polygon, py::arg("domain"), py::arg("max_size"), py::arg("size_field"),
        py::arg("refine_angle"), py::arg("protect_edges"), py::arg("quadtree"), py::arg("improve"),
        "mesh_polygon(domain, options); see pqmesh.triangulate.");
  m.def("triangulate_without_boundary_steiner", &run_no_steiner, py::arg("domain"), py::arg("refine_angle"),
        py::arg("keep_better_cdt"), py::arg("thesis_fans"), py::arg("quality_pass"), py::arg("min_angle"),
        "triangulate_without_boundary_steiner(domain, options); see pqmesh.triangulate.");
}

}  // namespace pqmesh::python
