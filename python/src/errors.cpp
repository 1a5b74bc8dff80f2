// Library exceptions -> the classes of pqmesh.errors (python/pqmesh/errors.py).
// str() of the Python exception is the C++ what(), the text the CLI prints
// after "pqmesh COMMAND: "; InputError carries code, ids, path, line, detail.
#include <pybind11/stl.h>

#include <exception>

#include "bindings.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/tetmesh.hpp"

namespace pqmesh::python {
namespace {

void raise(const char* name, py::object exception) {
  const py::object cls = py::module_::import("pqmesh.errors").attr(name);
  PyErr_SetObject(cls.ptr(), exception.ptr());
}

void raise_plain(const char* name, const std::exception& e) {
  raise(name, py::module_::import("pqmesh.errors").attr(name)(e.what()));
}

void raise_input(const char* name, const InvalidInput& e, const py::dict& extra = py::dict()) {
  const py::object cls = py::module_::import("pqmesh.errors").attr(name);
  const py::object path = e.file().empty() ? py::object(py::none()) : py::str(e.file());
  const py::object line = e.line() > 0 ? py::object(py::int_(e.line())) : py::object(py::none());
  raise(name, cls(e.what(), to_string(e.code()), e.ids(), path, line, e.detail(), **extra));
}

void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const MeshNotSupported& e) {
    raise_input("MeshNotSupported", e, py::dict(py::arg("kind") = e.kind()));
  } catch (const ParseError& e) {
    raise_input("ParseError", e);
  } catch (const DomainError& e) {
    raise_input("DomainError", e);
  } catch (const InvalidInput& e) {
    raise_input("InputError", e);
  } catch (const OutputError& e) {
    raise_plain("OutputError", e);
  } catch (const InternalError& e) {
    raise_plain("InternalError", e);
  } catch (const Error& e) {
    raise_plain("Error", e);
  }
}

}  // namespace

void bind_errors(py::module_&) { py::register_exception_translator(translate); }

}  // namespace pqmesh::python
