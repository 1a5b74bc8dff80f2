// pqmesh._pqmesh: the compiled part of the Python package pqmesh (the pure
// Python part, python/pqmesh, wraps it with argument handling and to_meshio).
#include "bindings.hpp"

PYBIND11_MODULE(_pqmesh, m) {
  using namespace pqmesh::python;
  m.doc() = "pqmesh library bindings (use the package pqmesh, not this module)";
  bind_errors(m);
  bind_domains(m);
  bind_meshes(m);
  bind_mesh2d(m);
  bind_mesh3d(m);
  bind_reports(m);
}
