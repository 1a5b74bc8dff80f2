#include "io/mesh_common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "predicates/predicates.hpp"
#include "pqmesh/errors.hpp"

namespace pqmesh::detail {

namespace {

void check_count(const std::vector<int>& markers, std::size_t expected, const char* what) {
  if (!markers.empty() && markers.size() != expected)
    throw InvalidInput(ErrorCode::WrongCount, std::string(what) + ": " + std::to_string(markers.size()) +
                                                  " markers for " + std::to_string(expected) + " items");
}

template <std::size_t N>
void check_indices(const std::vector<std::array<int, N>>& items, std::size_t num_vertices, const char* what) {
  for (std::size_t i = 0; i < items.size(); ++i)
    for (int v : items[i])
      if (v < 0 || static_cast<std::size_t>(v) >= num_vertices)
        throw InvalidInput(ErrorCode::IndexOutOfRange,
                           std::string(what) + " " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                               " of " + std::to_string(num_vertices),
                           {static_cast<std::int64_t>(i), v});
}

template <class M>
void check_mesh(const M& mesh, const WriteOptions& options) {
  using T = MeshTraits<M>;
  const std::size_t nv = mesh.vertices.size();
  if (nv > static_cast<std::size_t>(INT32_MAX) - 1)
    throw InvalidInput(ErrorCode::WrongCount, "too many vertices for the output formats");
  for (std::size_t i = 0; i < nv; ++i)
    for (int k = 0; k < T::dim; ++k)
      if (!std::isfinite(coord(mesh.vertices[i], k)))
        throw InvalidInput(ErrorCode::NonFinite, "vertex " + std::to_string(i) + " has a non-finite coordinate",
                           {static_cast<std::int64_t>(i)});
  check_count(mesh.vertex_markers, nv, "vertex markers");
  check_count(T::cell_markers(mesh), T::cells(mesh).size(), "element markers");
  check_count(T::face_markers(mesh), T::faces(mesh).size(), "boundary markers");
  check_indices(T::cells(mesh), nv, "element");
  check_indices(T::faces(mesh), nv, "boundary item");
  const std::size_t nc = T::cells(mesh).size();
  for (std::size_t f = 0; f < options.cell_fields.size(); ++f) {
    const CellField& field = options.cell_fields[f];
    const bool bad_name = field.name.empty() || field.name == "marker" || field.name == "vertex_marker" ||
                          field.name.find_first_of("\"<>&\n\r") != std::string::npos;
    if (bad_name) throw InvalidInput(ErrorCode::Syntax, "cell field name '" + field.name + "' is not allowed");
    for (std::size_t g = 0; g < f; ++g)
      if (options.cell_fields[g].name == field.name)
        throw InvalidInput(ErrorCode::WrongCount, "cell field '" + field.name + "' given twice");
    if (field.values.size() != nc)
      throw InvalidInput(ErrorCode::WrongCount, "cell field '" + field.name + "' has " +
                                                    std::to_string(field.values.size()) + " values for " +
                                                    std::to_string(nc) + " elements");
  }
}

// The markers, or none when they are all zero.
std::vector<int> unless_all_zero(std::vector<int> markers) {
  if (std::all_of(markers.begin(), markers.end(), [](int m) { return m == 0; })) markers.clear();
  return markers;
}

}  // namespace

void check_for_write(const TriMesh2& mesh, const WriteOptions& options) { check_mesh(mesh, options); }
void check_for_write(const TetMesh3& mesh, const WriteOptions& options) { check_mesh(mesh, options); }

TriMesh2 to_trimesh(RawMesh&& raw, const std::string& path) {
  TriMesh2 mesh;
  const std::size_t nv = raw.xyz.size() / 3;
  mesh.vertices.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    if (raw.xyz[3 * i + 2] != 0.0)
      throw ParseError(ErrorCode::Unsupported,
                       "vertex " + std::to_string(i) + " has z != 0; a 2D mesh must lie in the plane z = 0",
                       {static_cast<std::int64_t>(i)}, path, 0);
    mesh.vertices[i] = {raw.xyz[3 * i], raw.xyz[3 * i + 1]};
  }
  mesh.triangles.resize(raw.cells.size() / 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    // Kept in file order, never reoriented: a wrongly oriented element is the
    // checker's to report (pqmesh check), not the reader's to hide.
    mesh.triangles[t] = {raw.cells[3 * t], raw.cells[3 * t + 1], raw.cells[3 * t + 2]};
  }
  mesh.edges.resize(raw.faces.size() / 2);
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) mesh.edges[e] = {raw.faces[2 * e], raw.faces[2 * e + 1]};
  mesh.vertex_markers = unless_all_zero(std::move(raw.vertex_markers));
  mesh.triangle_markers = unless_all_zero(std::move(raw.cell_markers));
  mesh.edge_markers = unless_all_zero(std::move(raw.face_markers));
  return mesh;
}

TetMesh3 to_tetmesh(RawMesh&& raw, const std::string& /*path*/) {
  TetMesh3 mesh;
  const std::size_t nv = raw.xyz.size() / 3;
  mesh.vertices.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) mesh.vertices[i] = {raw.xyz[3 * i], raw.xyz[3 * i + 1], raw.xyz[3 * i + 2]};
  mesh.tetrahedra.resize(raw.cells.size() / 4);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    // Kept in file order, never reoriented (see to_trimesh).
    mesh.tetrahedra[t] = {raw.cells[4 * t], raw.cells[4 * t + 1], raw.cells[4 * t + 2], raw.cells[4 * t + 3]};
  }
  mesh.faces.resize(raw.faces.size() / 3);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    mesh.faces[f] = {raw.faces[3 * f], raw.faces[3 * f + 1], raw.faces[3 * f + 2]};
  mesh.vertex_markers = unless_all_zero(std::move(raw.vertex_markers));
  mesh.tetrahedron_markers = unless_all_zero(std::move(raw.cell_markers));
  mesh.face_markers = unless_all_zero(std::move(raw.face_markers));
  return mesh;
}

PhysicalGroups make_physical_groups(const std::vector<int>& markers, std::size_t count) {
  PhysicalGroups groups;
  if (markers.empty()) {
    if (count > 0) groups.markers.push_back(0);
  } else {
    groups.markers = markers;
    std::sort(groups.markers.begin(), groups.markers.end());
    groups.markers.erase(std::unique(groups.markers.begin(), groups.markers.end()), groups.markers.end());
  }
  const int largest = groups.markers.empty() ? 0 : std::max(groups.markers.back(), 0);
  for (int m : groups.markers) {
    const std::int64_t tag = m >= 1 ? m : std::int64_t{largest} + 1 - m;
    if (tag > INT32_MAX)
      throw InvalidInput(ErrorCode::WrongCount, "marker " + std::to_string(m) + " has no Gmsh physical tag (> 2^31-1)",
                         {m});
    groups.physical_tags.push_back(static_cast<int>(tag));
  }
  return groups;
}

int PhysicalGroups::entity_of(int marker) const {
  const auto it = std::lower_bound(markers.begin(), markers.end(), marker);
  return static_cast<int>(it - markers.begin()) + 1;
}

std::string tetgen_stem(const std::string& path) {
  for (const char* ext : {".node", ".ele", ".face", ".poly"}) {
    const std::string e(ext);
    if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
      return path.substr(0, path.size() - e.size());
  }
  return path;
}

}  // namespace pqmesh::detail
