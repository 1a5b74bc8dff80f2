// Domain2 / Domain3: validated input domains (make_domain), built from arrays
// or read from a file by read_domain as the CLI reads its INPUT (load.cpp).
// Arrays are read-only views into the domain (the domain object owns them)
// except where noted as copies.
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "pqmesh/alpha.hpp"
#include "pqmesh/domain.hpp"
#include "pqmesh/read_domain.hpp"

namespace pqmesh::python {
namespace {

std::shared_ptr<Domain2> domain2(py::handle points, py::handle segments, py::handle markers, py::handle holes,
                                 py::handle regions) {
  Pslg2 pslg;
  pslg.vertices = to_points2(points, "points");
  pslg.segments = to_index_rows<2>(segments, "segments");
  if (!markers.is_none()) pslg.segment_markers = to_ints(markers, "segment_markers", pslg.segments.size());
  if (!holes.is_none()) pslg.holes = to_points2(holes, "holes");
  if (!regions.is_none()) pslg.regions = to_regions2(regions);
  py::gil_scoped_release release;
  return std::make_shared<Domain2>(make_domain(std::move(pslg)));
}

std::shared_ptr<Domain3> domain3(py::handle points, py::handle facets, py::handle markers, py::handle holes,
                                 py::handle regions) {
  Plc3 plc;
  plc.vertices = to_points3(points, "points");
  plc.facets = to_facets(facets);
  if (!markers.is_none()) {
    const std::vector<int> m = to_ints(markers, "facet_markers", plc.facets.size());
    for (std::size_t f = 0; f < m.size(); ++f) plc.facets[f].marker = m[f];
  }
  if (!holes.is_none()) plc.holes = to_points3(holes, "holes");
  if (!regions.is_none()) plc.regions = to_regions3(regions);
  py::gil_scoped_release release;
  return std::make_shared<Domain3>(make_domain(std::move(plc)));
}

// Python's form of read_domain: a Domain2 or a Domain3 by the file's dimension.
py::object read_domain(const std::string& path, bool merge_coplanar, double merge_angle) {
  if (!(merge_angle >= 0 && merge_angle < 90)) throw py::value_error("merge_angle must be in [0, 90) degrees");
  const ReadOptions options{merge_coplanar, merge_angle};
  std::shared_ptr<Domain2> d2;
  std::shared_ptr<Domain3> d3;
  {
    py::gil_scoped_release release;
    if (domain_dimension(path) == 2)
      d2 = std::make_shared<Domain2>(make_domain(read_pslg(path)));
    else
      d3 = std::make_shared<Domain3>(make_domain(read_plc(path, options)));
  }
  return d2 ? py::cast(d2) : py::cast(d3);
}

py::object path_or_none(const SourceInfo& source) {
  return source.path.empty() ? py::object(py::none()) : py::object(py::str(source.path));
}

// A facet as the constructor takes it: its loop, or its list of loops when it has holes.
py::object facet_loops(const Facet3& facet) {
  if (facet.loops.size() == 1) return py::cast(facet.loops[0]);
  return py::cast(facet.loops);
}

void bind_domain2(py::module_& m) {
  py::class_<Domain2, std::shared_ptr<Domain2>>(m, "Domain2", "A validated polygon with holes (make_domain).")
      .def(py::init(&domain2), py::arg("points"), py::arg("segments"), py::arg("segment_markers") = py::none(),
           py::arg("holes") = py::none(), py::arg("regions") = py::none())
      .def_property_readonly("dimension", [](const Domain2&) { return 2; })
      .def_property_readonly("points", [](py::object self) { return view(self.cast<const Domain2&>().pslg.vertices, self); })
      .def_property_readonly("segments", [](py::object self) { return view(self.cast<const Domain2&>().pslg.segments, self); })
      .def_property_readonly("segment_markers",
                             [](py::object self) { return markers_or_none(self.cast<const Domain2&>().pslg.segment_markers, self); })
      .def_property_readonly("holes", [](py::object self) { return view(self.cast<const Domain2&>().pslg.holes, self); })
      .def_property_readonly("loops", [](const Domain2& d) { return d.loops; },
                             "Vertex ids of each boundary loop (a copy): the outer one counter-clockwise, holes clockwise.")
      .def_property_readonly("area", [](const Domain2& d) { return d.area; })
      .def_property_readonly("path", [](const Domain2& d) { return path_or_none(d.pslg.source); })
      .def_property_readonly("first_id", [](const Domain2& d) { return d.pslg.source.first_id; },
                             "The file's numbering base: ids in messages are index + first_id.")
      .def_property_readonly("alpha", [](const Domain2& d) { return compute_alpha(d.pslg.vertices, d.loops).degrees(); },
                             "The smallest interior angle of the polygon, degrees.")
      .def("__repr__", [](const Domain2& d) {
        return "Domain2(" + std::to_string(d.pslg.vertices.size()) + " vertices, " + std::to_string(d.pslg.segments.size()) +
               " segments, " + std::to_string(d.loops.size() - 1) + " holes)";
      });
}

void bind_domain3(py::module_& m) {
  py::class_<Domain3, std::shared_ptr<Domain3>>(m, "Domain3", "A validated polyhedral domain (make_domain).")
      .def(py::init(&domain3), py::arg("points"), py::arg("facets"), py::arg("facet_markers") = py::none(),
           py::arg("holes") = py::none(), py::arg("regions") = py::none())
      .def_property_readonly("dimension", [](const Domain3&) { return 3; })
      .def_property_readonly("points", [](py::object self) { return view(self.cast<const Domain3&>().plc.vertices, self); })
      .def_property_readonly("facets", [](const Domain3& d) {
        py::list out;
        for (const Facet3& f : d.plc.facets) out.append(facet_loops(f));
        return out;
      }, "Each facet's loop (a list of loops when it has holes), oriented outward (a copy).")
      .def_property_readonly("facet_markers", [](const Domain3& d) {
        py::array_t<int> out(static_cast<py::ssize_t>(d.plc.facets.size()));
        for (std::size_t f = 0; f < d.plc.facets.size(); ++f) out.mutable_at(static_cast<py::ssize_t>(f)) = d.plc.facets[f].marker;
        return out;
      }, "One marker per facet (a copy).")
      .def_property_readonly("holes", [](py::object self) { return view(self.cast<const Domain3&>().plc.holes, self); })
      .def_property_readonly("volume", [](const Domain3& d) { return d.volume; })
      .def_property_readonly("shells", [](const Domain3& d) { return d.shells.size(); },
                             "Connected components of the boundary: 1 + the number of cavities.")
      .def_property_readonly("path", [](const Domain3& d) { return path_or_none(d.plc.source); })
      .def_property_readonly("first_id", [](const Domain3& d) { return d.plc.source.first_id; },
                             "The file's numbering base: ids in messages are index + first_id.")
      .def_property_readonly("alpha", [](const Domain3& d) { return compute_alpha(d.plc).degrees(); },
                             "alpha of thesis ch. 3: the smallest interior angle between faces, degrees.")
      .def("__repr__", [](const Domain3& d) {
        return "Domain3(" + std::to_string(d.plc.vertices.size()) + " vertices, " + std::to_string(d.plc.facets.size()) +
               " facets, " + std::to_string(d.shells.size()) + " shells)";
      });
}

}  // namespace

void bind_domains(py::module_& m) {
  bind_domain2(m);
  bind_domain3(m);
  m.def("read_domain", &read_domain, py::arg("path"), py::arg("merge_coplanar") = true, py::arg("merge_angle") = 0.0,
        "Read and validate a domain file as `pqmesh mesh INPUT` does: a Domain2 for a 2D file, else a Domain3.");
}

}  // namespace pqmesh::python
