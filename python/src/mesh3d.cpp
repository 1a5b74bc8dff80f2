// tet_mesh as `pqmesh mesh` runs it on a 3D domain (cmd_mesh3.cpp): the mesh,
// then alpha and the quality figures of the CLI's summary, all computed with
// the GIL released. The figures become attributes of the returned TetMesh.
#include <memory>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/quality.hpp"
#include "pqmesh/tetmesh.hpp"
#include "timed.hpp"

namespace pqmesh::python {
namespace {

py::dict stats_dict(const TetMeshStats& s) {
  py::dict per_kind;
  for (int k = 0; k < kTetLeafKinds; ++k) per_kind[tet_leaf_kind_name(k)] = s.leaves_per_kind[static_cast<std::size_t>(k)];
  return py::dict(py::arg("leaves") = s.leaves, py::arg("leaves_per_kind") = per_kind,
                  py::arg("flush_leaves") = s.flush_leaves, py::arg("touching_leaves") = s.touching_leaves,
                  py::arg("empty_jobs") = s.empty_jobs, py::arg("facet_jobs") = s.facet_jobs,
                  py::arg("edge_jobs") = s.edge_jobs, py::arg("vertex_jobs") = s.vertex_jobs,
                  py::arg("two_facet_jobs") = s.two_facet_jobs, py::arg("facet_inside") = s.facet_inside,
                  py::arg("facet_on") = s.facet_on, py::arg("facet_beyond") = s.facet_beyond,
                  py::arg("warped") = s.warped, py::arg("warp_rebuilds") = s.warp_rebuilds,
                  py::arg("worst_box_rounds") = s.worst_box_rounds,
                  py::arg("box_runs") = s.box_runs, py::arg("wider_table") = s.wider_table, py::arg("split_squares") = s.split_squares,
                  py::arg("warp_failure") = s.warp_failure, py::arg("boundary_faces") = s.boundary_faces,
                  py::arg("separated") = s.separated,
                  py::arg("separated_faces") = s.separated_faces, py::arg("extended_margin") = s.extended_margin,
                  py::arg("light_rejected") = s.light_rejected,
                  py::arg("constructed_tetrahedra") = s.constructed_tetrahedra,
                  py::arg("constructed_max_aspect") = s.constructed_max_aspect, py::arg("collapses") = s.collapses,
                  py::arg("smoothed") = s.smoothed, py::arg("flips") = s.flips, py::arg("boundary_flips") = s.boundary_flips,
                  py::arg("min_dihedral_target") = s.min_dihedral_target,
                  py::arg("improve_failure") = s.improve_failure,
                  py::arg("depth") = s.depth, py::arg("root_size") = s.root_size,
                  py::arg("grid_offset") = py::make_tuple(s.grid_offset[0], s.grid_offset[1], s.grid_offset[2]),
                  py::arg("grid_shift") = s.grid_shift);
}

py::object run_tet_mesh(std::shared_ptr<Domain3> domain, double max_size, py::object size_field, bool generic_grid,
                        bool warp, bool full_separation, bool improve, double target_aspect, py::object min_dihedral) {
  if (!(target_aspect >= 3)) throw py::value_error("target_aspect must be at least 3 (the regular tetrahedron)");
  const std::optional<double> target =
      min_dihedral.is_none() ? std::nullopt : std::optional<double>(min_dihedral.cast<double>());
  if (target && !(*target >= 0 && *target < 70.5))
    throw py::value_error("min_dihedral must be at least 0 and below 70.5 degrees (the regular tetrahedron's)");
  TetMeshOptions options;
  options.improve = improve;
  options.target_aspect = target_aspect;
  options.min_dihedral = target;
  if (full_separation) options.separation = TetSeparation::Always;
  options.max_size = max_size;
  options.generic_grid = generic_grid;
  options.warp = warp;
  // A size-field file (read_size_field3: "x y z size" lines) or a pair (points
  // (K, 3), sizes (K,)): the size asked for at x is min_i sizes[i] + |x - points[i]|.
  if (!size_field.is_none()) options.size_field = to_size_field(size_field, read_size_field3, to_points3);
  TetMeshResult result;
  AlphaResult alpha;
  QualityReport quality;
  double seconds = 0;
  {
    py::gil_scoped_release release;
    seconds = seconds_of([&] { result = tet_mesh(*domain, options); });
    alpha = compute_alpha(domain->plc);
    quality = quality_report(result.mesh);
  }
  const TetMeshStats& s = result.stats;
  py::object mesh = py::cast(std::make_shared<TetMesh3>(std::move(result.mesh)));
  mesh.attr("domain") = domain;
  mesh.attr("alpha") = alpha.degrees();
  mesh.attr("max_aspect_ratio") = quality.aspect_ratio.max;
  mesh.attr("aspect_bound") = kMeasuredAspectAlphaC / alpha.radians;
  mesh.attr("min_dihedral") = quality.min_angle.min;
  mesh.attr("max_dihedral") = quality.max_angle.max;
  mesh.attr("stats") = stats_dict(s);
  mesh.attr("seconds") = py::dict(py::arg("octree") = s.seconds_octree, py::arg("classify") = s.seconds_classify,
                                  py::arg("tetrahedra") = s.seconds_tetrahedra, py::arg("boundary") = s.seconds_boundary,
                                  py::arg("light") = s.seconds_light, py::arg("improve") = s.seconds_improve,
                                  py::arg("mesh") = seconds);
  return mesh;
}

}  // namespace

void bind_mesh3d(py::module_& m) {
  m.def("tet_mesh", &run_tet_mesh, py::arg("domain"), py::arg("max_size"), py::arg("size_field"),
        py::arg("generic_grid"), py::arg("warp"), py::arg("full_separation"), py::arg("improve"),
        py::arg("target_aspect"), py::arg("min_dihedral"),
        "tet_mesh(domain, options); see pqmesh.tetrahedralize.");
}

}  // namespace pqmesh::python
