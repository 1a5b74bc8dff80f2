#pragma once
// The parts of the extension module pqmesh._pqmesh, one per source file; each
// adds its classes and functions to the module. Only include/pqmesh headers
// are used: the module calls the library's public entry points, as the CLI does.
#include <pybind11/pybind11.h>

namespace pqmesh::python {

namespace py = pybind11;

void bind_errors(py::module_& m);    // errors.cpp: C++ exceptions -> pqmesh.errors classes
void bind_domains(py::module_& m);   // domains.cpp: Domain2, Domain3, read_domain
void bind_meshes(py::module_& m);    // meshes.cpp: TriMesh, TetMesh
void bind_mesh2d(py::module_& m);    // mesh2d.cpp: quad_mesh, triangulate_no_boundary_steiner
void bind_mesh3d(py::module_& m);    // mesh3d.cpp: tet_mesh
void bind_reports(py::module_& m);   // reports.cpp: check, check_topology, quality

}  // namespace pqmesh::python
