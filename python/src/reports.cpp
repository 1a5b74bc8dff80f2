// The validity checker and the quality measures, as `pqmesh check` and
// `pqmesh quality` run them (cmd_check.cpp, cmd_quality.cpp), with the GIL
// released. check() pairs a TriMesh with a Domain2 and a TetMesh with a Domain3.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "bindings.hpp"
#include "pqmesh/check.hpp"
#include "pqmesh/quality.hpp"

namespace pqmesh::python {
namespace {

CheckReport run_check(py::handle mesh, py::handle domain, const CheckOptions& options) {
  if (py::isinstance<TriMesh2>(mesh) && py::isinstance<Domain2>(domain)) {
    const auto m = mesh.cast<std::shared_ptr<TriMesh2>>();
    const auto d = domain.cast<std::shared_ptr<Domain2>>();
    py::gil_scoped_release release;
    return check_mesh(*m, *d, options);
  }
  if (py::isinstance<TetMesh3>(mesh) && py::isinstance<Domain3>(domain)) {
    const auto m = mesh.cast<std::shared_ptr<TetMesh3>>();
    const auto d = domain.cast<std::shared_ptr<Domain3>>();
    py::gil_scoped_release release;
    return check_mesh(*m, *d, options);
  }
  throw py::type_error("check needs a TriMesh with a Domain2 or a TetMesh with a Domain3");
}

CheckReport check(py::handle mesh, py::handle domain, bool no_boundary_steiner, std::size_t max_issues,
                  bool locate_vertices) {
  CheckOptions options;
  options.no_boundary_steiner = no_boundary_steiner;
  options.max_issues_per_kind = max_issues;
  options.locate_vertices = locate_vertices;
  return run_check(mesh, domain, options);
}

CheckReport check_topology(py::handle mesh) {
  if (py::isinstance<TriMesh2>(mesh)) {
    const auto m = mesh.cast<std::shared_ptr<TriMesh2>>();
    py::gil_scoped_release release;
    return check_mesh_topology(*m);
  }
  const auto m = mesh.cast<std::shared_ptr<TetMesh3>>();
  py::gil_scoped_release release;
  return check_mesh_topology(*m);
}

// quality_report plus the per-element values it summarises (numpy copies in
// the attribute `per_element`: min_angle, max_angle, aspect_ratio,
// sphere_ratio, radius_edge, size; angles are dihedral angles in 3D).
template <class Mesh, class Quality>
py::object quality(const Mesh& mesh) {
  std::vector<Quality> elements;
  QualityReport report;
  {
    py::gil_scoped_release release;
    elements = element_quality(mesh);
    report = quality_report(std::span<const Quality>(elements));
  }
  const auto n = static_cast<py::ssize_t>(elements.size());
  py::array_t<double> lo(n), hi(n), aspect(n), sphere(n), radius_edge(n), size(n);
  for (py::ssize_t e = 0; e < n; ++e) {
    const Quality& q = elements[static_cast<std::size_t>(e)];
    if constexpr (std::is_same_v<Quality, TriQuality>) {
      lo.mutable_at(e) = q.min_angle_deg;
      hi.mutable_at(e) = q.max_angle_deg;
      size.mutable_at(e) = q.area;
    } else {
      lo.mutable_at(e) = q.min_dihedral_deg;
      hi.mutable_at(e) = q.max_dihedral_deg;
      size.mutable_at(e) = q.volume;
    }
    aspect.mutable_at(e) = q.aspect_ratio;
    sphere.mutable_at(e) = q.sphere_ratio;
    radius_edge.mutable_at(e) = q.radius_edge;
  }
  py::object out = py::cast(std::move(report));
  out.attr("per_element") = py::dict(py::arg("min_angle") = lo, py::arg("max_angle") = hi, py::arg("aspect_ratio") = aspect,
                                     py::arg("sphere_ratio") = sphere, py::arg("radius_edge") = radius_edge,
                                     py::arg("size") = size);
  return out;
}

void bind_check_report(py::module_& m) {
  py::class_<CheckIssue>(m, "CheckIssue")
      .def_property_readonly("kind", [](const CheckIssue& i) { return to_string(i.kind); })
      .def_readonly("ids", &CheckIssue::ids)
      .def_readonly("message", &CheckIssue::message)
      .def("__repr__", [](const CheckIssue& i) { return std::string(to_string(i.kind)) + ": " + i.message; });
  py::class_<CheckReport>(m, "CheckReport", "The validity checker's report (pqmesh::CheckReport).")
      .def_property_readonly("valid", &CheckReport::valid)
      .def_readonly("dimension", &CheckReport::dimension)
      .def_readonly("vertices", &CheckReport::vertices)
      .def_readonly("elements", &CheckReport::elements)
      .def_readonly("boundary_faces", &CheckReport::boundary_faces)
      .def_readonly("domain_checked", &CheckReport::domain_checked)
      .def_readonly("volume_measured", &CheckReport::volume_measured)
      .def_readonly("mesh_volume", &CheckReport::mesh_volume)
      .def_readonly("domain_volume", &CheckReport::domain_volume)
      .def_readonly("issues", &CheckReport::issues)
      .def_readonly("notes", &CheckReport::notes)
      .def_property_readonly("messages", [](const CheckReport& r) {
        std::vector<std::string> out;
        for (const CheckIssue& i : r.issues) out.push_back(i.message);
        return out;
      }, "The message of every stored issue, in stage order.")
      .def_property_readonly("counts", [](const CheckReport& r) {
        py::dict out;
        for (CheckKind k : r.kinds()) out[to_string(k)] = r.count(k);
        return out;
      }, "Issues per kind (all of them, also those not stored), kinds with none left out.")
      .def_property_readonly("text", &CheckReport::to_text, "The report as `pqmesh check` prints it.")
      .def("__str__", &CheckReport::to_text)
      .def("__repr__", [](const CheckReport& r) { return "<CheckReport " + r.to_text().substr(0, r.to_text().find('\n')) + ">"; });
}

void bind_quality_report(py::module_& m) {
  py::class_<Stat>(m, "Stat", "Minimum, maximum and mean over the elements; argmin/argmax: the first element attaining them.")
      .def_readonly("min", &Stat::min)
      .def_readonly("max", &Stat::max)
      .def_readonly("mean", &Stat::mean)
      .def_readonly("argmin", &Stat::argmin)
      .def_readonly("argmax", &Stat::argmax)
      .def("__repr__", [](const Stat& s) {
        return "Stat(min=" + std::to_string(s.min) + ", max=" + std::to_string(s.max) + ", mean=" + std::to_string(s.mean) + ")";
      });
  py::class_<Histogram>(m, "Histogram")
      .def_readonly("measure", &Histogram::measure)
      .def_readonly("edges", &Histogram::edges)
      .def_readonly("counts", &Histogram::counts);
  py::class_<QualityReport>(m, "QualityReport", py::dynamic_attr(),
                            "The measures of thesis ch. 3 (pqmesh::QualityReport); angles in degrees, dihedral in 3D.")
      .def_readonly("dimension", &QualityReport::dimension)
      .def_readonly("elements", &QualityReport::elements)
      .def_readonly("degenerate", &QualityReport::degenerate)
      .def_readonly("inverted", &QualityReport::inverted)
      .def_readonly("min_angle", &QualityReport::min_angle)
      .def_readonly("max_angle", &QualityReport::max_angle)
      .def_readonly("aspect_ratio", &QualityReport::aspect_ratio)
      .def_readonly("sphere_ratio", &QualityReport::sphere_ratio)
      .def_readonly("radius_edge", &QualityReport::radius_edge)
      .def_readonly("size", &QualityReport::size)
      .def_readonly("total_size", &QualityReport::total_size)
      .def_readonly("min_angle_hist", &QualityReport::min_angle_hist)
      .def_readonly("max_angle_hist", &QualityReport::max_angle_hist)
      .def_readonly("aspect_hist", &QualityReport::aspect_hist)
      .def_property_readonly("text", &QualityReport::to_text, "The report as `pqmesh quality` prints it.")
      .def("__str__", &QualityReport::to_text);
}

}  // namespace

void bind_reports(py::module_& m) {
  bind_check_report(m);
  bind_quality_report(m);
  m.def("check", &check, py::arg("mesh"), py::arg("domain"), py::arg("no_boundary_steiner") = false,
        py::arg("max_issues") = 20, py::arg("locate_vertices") = true,
        "check_mesh(mesh, domain, options): the full validity check against the input domain.");
  m.def("check_topology", &check_topology, py::arg("mesh"),
        "check_mesh_topology(mesh): orientation, conformity, closed boundary; no domain.");
  m.def("quality", [](const TriMesh2& mesh) { return quality<TriMesh2, TriQuality>(mesh); }, py::arg("mesh"));
  m.def("quality", [](const TetMesh3& mesh) { return quality<TetMesh3, TetQuality>(mesh); }, py::arg("mesh"),
        "quality_report(mesh) with the per-element values in .per_element.");
}

}  // namespace pqmesh::python
