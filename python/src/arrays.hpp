#pragma once
// Conversions between Python arrays (numpy arrays or nested sequences) and the
// library's vectors, and read-only numpy views of the library's vectors.
//
// Input contract: every converter accepts whatever numpy.asarray accepts and
// checks shape and dtype; on a mismatch it throws pqmesh::InvalidInput
// (Python: pqmesh.InputError) naming the argument, with code "wrong-count" for
// a wrong shape or length and "syntax" for entries of the wrong type; an index
// outside the int range gives "index-out-of-range" with ids = {row}. Index
// VALUES are not checked against the vertex count here: make_domain and the
// checker do that and name the offending elements. An empty input (size 0) is
// an empty vector whatever its shape.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "pqmesh/plc.hpp"
#include "pqmesh/vec.hpp"

namespace pqmesh::python {

namespace py = pybind11;

// expected_size value meaning "any length".
inline constexpr std::size_t kAnySize = static_cast<std::size_t>(-1);

// An (N, 2) / (N, 3) array of numbers.
std::vector<Vec2> to_points2(py::handle obj, const char* name);
std::vector<Vec3> to_points3(py::handle obj, const char* name);

// A 1-D array of numbers / integers; its length must be expected_size unless kAnySize.
std::vector<double> to_doubles(py::handle obj, const char* name, std::size_t expected_size = kAnySize);
std::vector<int> to_ints(py::handle obj, const char* name, std::size_t expected_size = kAnySize);

// An (N, K) array of integers, e.g. segments (K = 2) or tetrahedra (K = 4).
template <std::size_t K>
std::vector<std::array<int, K>> to_index_rows(py::handle obj, const char* name);

// Facets: a sequence whose items are a loop of vertex ids (a polygon) or a
// sequence of loops (the outer boundary, then holes); also an (F, K) integer
// array. Errors name the facet: ids = {facet}.
std::vector<Facet3> to_facets(py::handle obj);

// Regions: rows (x, y[, z], attribute[, max size]).
std::vector<Region2> to_regions2(py::handle obj);
std::vector<Region3> to_regions3(py::handle obj);

// A size field: a file name (read by `read`, e.g. read_size_field2) or a pair
// (points, sizes) whose points `points` converts (to_points2 / to_points3).
template <class Field, class Points>
Field to_size_field(py::handle obj, Field (*read)(const std::string&), Points (*points)(py::handle, const char*)) {
  if (py::isinstance<py::str>(obj)) return read(obj.cast<std::string>());
  if (!py::isinstance<py::sequence>(obj) || py::len(obj) != 2)
    throw py::value_error("size_field must be a file name or a pair (points, sizes)");
  Field field;
  field.points = points(obj[py::int_(0)], "size_field points");
  field.sizes = to_doubles(obj[py::int_(1)], "size_field sizes", field.points.size());
  return field;
}

// A read-only numpy array of shape `shape` over `data`, kept alive by `owner`
// (the Python object that owns the vector). Scalars are double or int.
py::array view(const double* data, std::vector<py::ssize_t> shape, py::handle owner);
py::array view(const int* data, std::vector<py::ssize_t> shape, py::handle owner);

// (N, 2) / (N, 3) float64 views of points, (N, K) int32 views of index rows.
static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Vec3) == 3 * sizeof(double));
inline py::array view(const std::vector<Vec2>& points, py::handle owner) {
  return view(reinterpret_cast<const double*>(points.data()), {static_cast<py::ssize_t>(points.size()), 2}, owner);
}
inline py::array view(const std::vector<Vec3>& points, py::handle owner) {
  return view(reinterpret_cast<const double*>(points.data()), {static_cast<py::ssize_t>(points.size()), 3}, owner);
}
template <std::size_t K>
py::array view(const std::vector<std::array<int, K>>& rows, py::handle owner) {
  static_assert(sizeof(std::array<int, K>) == K * sizeof(int));
  return view(reinterpret_cast<const int*>(rows.data()),
              {static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(K)}, owner);
}

// A 1-D array over a marker vector, or None when the vector is empty.
py::object markers_or_none(const std::vector<int>& markers, py::handle owner);

}  // namespace pqmesh::python
