#include "arrays.hpp"

#include <climits>
#include <cstdint>
#include <string>
#include <utility>

#include "pqmesh/errors.hpp"

namespace pqmesh::python {
namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Int64Array = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

[[noreturn]] void fail(ErrorCode code, const std::string& detail, std::vector<std::int64_t> ids = {}) {
  throw InvalidInput(code, detail, std::move(ids));
}

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// numpy.asarray(obj) with its dtype kind in `kinds` ("iu": integers, "iuf":
// numbers), ndim dimensions and, for ndim 2, between min_cols and max_cols
// columns. Returns an empty array for size 0 without checking the shape.
py::array checked(py::handle obj, const std::string& name, const char* kinds, int ndim, py::ssize_t min_cols = 0,
                  py::ssize_t max_cols = 0) {
  py::array a;
  try {
    a = py::module_::import("numpy").attr("asarray")(obj);
  } catch (const py::error_already_set& e) {
    fail(ErrorCode::Syntax, name + " is not an array: " + e.what());
  }
  if (a.size() == 0) return a;
  if (std::string(kinds).find(a.dtype().kind()) == std::string::npos)
    fail(ErrorCode::Syntax, name + " must hold " + (std::string(kinds) == "iu" ? "integers" : "numbers") +
                                ", got dtype " + std::string(py::str(a.dtype())));
  const bool cols_ok = ndim == 1 || (a.ndim() == 2 && a.shape(1) >= min_cols && a.shape(1) <= max_cols);
  if (a.ndim() != ndim || !cols_ok) {
    const std::string want = ndim == 1 ? "(N,)"
                                        : "(N, " + std::to_string(min_cols) +
                                              (max_cols > min_cols ? " or " + std::to_string(max_cols) : "") + ")";
    fail(ErrorCode::WrongCount, name + " must have shape " + want + ", got " + shape_text(a));
  }
  return a;
}

int to_int(std::int64_t v, const std::string& name, std::int64_t row) {
  if (v < INT_MIN || v > INT_MAX)
    fail(ErrorCode::IndexOutOfRange, name + " entry " + std::to_string(row) + " holds " + std::to_string(v) +
                                         ", outside the 32-bit range", {row});
  return static_cast<int>(v);
}

void check_size(std::size_t size, std::size_t expected, const std::string& name) {
  if (expected != kAnySize && size != expected)
    fail(ErrorCode::WrongCount,
         name + " must have " + std::to_string(expected) + " entries, got " + std::to_string(size));
}

bool is_nested(py::handle item) {
  if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item) || py::len(item) == 0) return false;
  const py::object first = item[py::int_(0)];
  return py::isinstance<py::sequence>(first) && !py::isinstance<py::str>(first);
}

// The point whose coordinates start at p.
Vec2 vec2_at(const double* p) { return {p[0], p[1]}; }
Vec3 vec3_at(const double* p) { return {p[0], p[1], p[2]}; }

// An (N, dim) array of numbers, each row made a point by `point`.
template <class Point>
std::vector<Point> points(py::handle obj, const char* name, int dim, Point (*point)(const double*)) {
  const py::array a = checked(obj, name, "iuf", 2, dim, dim);
  std::vector<Point> out;
  if (a.size() == 0) return out;
  const DoubleArray d = DoubleArray::ensure(a);  // a converted copy must outlive the proxy
  out.reserve(static_cast<std::size_t>(d.shape(0)));
  for (py::ssize_t i = 0; i < d.shape(0); ++i) out.push_back(point(d.data(i, 0)));
  return out;
}

// A 1-D array with dtype kind in `kinds`, entry i converted by convert(value, i); its length must be expected_size.
template <class T, class Array, class Convert>
std::vector<T> entries(py::handle obj, const char* name, const char* kinds, std::size_t expected_size,
                       Convert convert) {
  const py::array a = checked(obj, name, kinds, 1);
  std::vector<T> out;
  if (a.size() > 0) {
    const Array d = Array::ensure(a);
    const auto r = d.template unchecked<1>();
    for (py::ssize_t i = 0; i < r.shape(0); ++i) out.push_back(convert(r(i), i));
  }
  check_size(out.size(), expected_size, name);
  return out;
}

template <class Region, class Point>
std::vector<Region> regions(py::handle obj, int dim, Point (*point)(const double*)) {
  const py::array a = checked(obj, "regions", "iuf", 2, dim + 1, dim + 2);
  std::vector<Region> out;
  if (a.size() == 0) return out;
  const DoubleArray d = DoubleArray::ensure(a);
  for (py::ssize_t i = 0; i < d.shape(0); ++i) {
    const double* row = d.data(i, 0);
    out.push_back({point(row), row[dim], d.shape(1) > dim + 1 ? row[dim + 1] : -1});
  }
  return out;
}

template <class T>
py::array make_view(const T* data, std::vector<py::ssize_t> shape, py::handle owner) {
  py::ssize_t size = 1;
  for (py::ssize_t s : shape) size *= s;
  py::array a = size == 0 ? py::array(py::dtype::of<T>(), shape, std::vector<py::ssize_t>{})
                          : py::array(py::dtype::of<T>(), shape, std::vector<py::ssize_t>{}, data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

}  // namespace

std::vector<Vec2> to_points2(py::handle obj, const char* name) { return points<Vec2>(obj, name, 2, vec2_at); }

std::vector<Vec3> to_points3(py::handle obj, const char* name) { return points<Vec3>(obj, name, 3, vec3_at); }

std::vector<double> to_doubles(py::handle obj, const char* name, std::size_t expected_size) {
  return entries<double, DoubleArray>(obj, name, "iuf", expected_size, [](double v, py::ssize_t) { return v; });
}

std::vector<int> to_ints(py::handle obj, const char* name, std::size_t expected_size) {
  return entries<int, Int64Array>(obj, name, "iu", expected_size,
                                  [&](std::int64_t v, py::ssize_t i) { return to_int(v, name, i); });
}

template <std::size_t K>
std::vector<std::array<int, K>> to_index_rows(py::handle obj, const char* name) {
  constexpr auto k = static_cast<py::ssize_t>(K);
  const py::array a = checked(obj, name, "iu", 2, k, k);
  std::vector<std::array<int, K>> out;
  if (a.size() == 0) return out;
  const Int64Array d = Int64Array::ensure(a);
  const auto r = d.unchecked<2>();
  out.resize(static_cast<std::size_t>(r.shape(0)));
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    for (py::ssize_t j = 0; j < k; ++j) out[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = to_int(r(i, j), name, i);
  return out;
}

template std::vector<std::array<int, 2>> to_index_rows<2>(py::handle, const char*);
template std::vector<std::array<int, 3>> to_index_rows<3>(py::handle, const char*);
template std::vector<std::array<int, 4>> to_index_rows<4>(py::handle, const char*);

std::vector<Facet3> to_facets(py::handle obj) {
  if (!py::isinstance<py::sequence>(obj) || py::isinstance<py::str>(obj))
    fail(ErrorCode::Syntax, "facets must be a sequence of polygons (lists of vertex ids)");
  std::vector<Facet3> out;
  const auto count = static_cast<std::int64_t>(py::len(obj));
  for (std::int64_t f = 0; f < count; ++f) {
    const py::object item = obj[py::int_(f)];
    const std::string name = "facet " + std::to_string(f);
    Facet3 facet;
    try {
      if (is_nested(item)) {
        for (py::handle loop : item) facet.loops.push_back(to_ints(loop, name.c_str()));
      } else {
        facet.loops.push_back(to_ints(item, name.c_str()));
      }
    } catch (const InvalidInput& e) {  // name the facet, not the position inside it
      fail(e.code(), e.detail(), {f});
    }
    out.push_back(std::move(facet));
  }
  return out;
}

std::vector<Region2> to_regions2(py::handle obj) {
  return regions<Region2, Vec2>(obj, 2, vec2_at);
}

std::vector<Region3> to_regions3(py::handle obj) {
  return regions<Region3, Vec3>(obj, 3, vec3_at);
}

py::array view(const double* data, std::vector<py::ssize_t> shape, py::handle owner) {
  return make_view(data, std::move(shape), owner);
}

py::array view(const int* data, std::vector<py::ssize_t> shape, py::handle owner) {
  return make_view(data, std::move(shape), owner);
}

py::object markers_or_none(const std::vector<int>& markers, py::handle owner) {
  if (markers.empty()) return py::none();
  return view(markers.data(), {static_cast<py::ssize_t>(markers.size())}, owner);
}

}  // namespace pqmesh::python
