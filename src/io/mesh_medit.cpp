// Medit .mesh, ASCII (MeshVersionFormatted 2: double precision). Written:
//   Dimension 2: Vertices (x y ref), Triangles (a b c ref), Edges (a b ref)
//   Dimension 3: Vertices (x y z ref), Tetrahedra (a b c d ref),
//                Triangles (boundary faces, a b c ref)
// 1-based vertex numbers; a missing marker is written as ref 0. Tetrahedra
// keep pqmesh's positive orientation; the reader keeps the file's order.
#include <algorithm>
#include <string>
#include <vector>

#include "io/mesh_common.hpp"
#include "io/mesh_input.hpp"
#include "io/mesh_output.hpp"

namespace pqmesh::detail {

namespace {

template <std::size_t N>
void put_items(BufferedWriter& out, const char* keyword, const std::vector<std::array<int, N>>& items,
               const std::vector<int>& markers) {
  out.put(keyword).put('\n').put_int(static_cast<std::int64_t>(items.size())).put('\n');
  for (std::size_t i = 0; i < items.size(); ++i) {
    for (int v : items[i]) out.put_int(v + 1).put(' ');
    out.put_int(marker_or_zero(markers, i)).put('\n');
  }
}

}  // namespace

template <class M>
void write_medit(const M& mesh, const std::string& path) {
  using T = MeshTraits<M>;
  AtomicFile file(path);
  BufferedWriter out(file.file(), path);
  out.put("MeshVersionFormatted 2\nDimension ").put_int(T::dim).put("\nVertices\n");
  out.put_int(static_cast<std::int64_t>(mesh.vertices.size())).put('\n');
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (int k = 0; k < T::dim; ++k) out.put_double(coord(mesh.vertices[i], k)).put(' ');
    out.put_int(marker_or_zero(mesh.vertex_markers, i)).put('\n');
  }
  put_items(out, T::dim == 2 ? "Triangles" : "Tetrahedra", T::cells(mesh), T::cell_markers(mesh));
  put_items(out, T::dim == 2 ? "Edges" : "Triangles", T::faces(mesh), T::face_markers(mesh));
  out.put("End\n");
  out.flush();
  file.commit();
}

template void write_medit(const TriMesh2&, const std::string&);
template void write_medit(const TetMesh3&, const std::string&);

RawMesh read_medit(const std::string& path, int dim) {
  std::string text = read_whole_file(path);
  // Every number takes at least two bytes (digit and separator): an announced
  // count is reserved only up to what the file can hold, so an absurd count
  // reads to the end and fails as Truncated instead of allocating.
  const std::int64_t max_numbers = static_cast<std::int64_t>(text.size() / 2 + 1);
  TextReader in(path, std::move(text), '#');
  RawMesh raw;
  int file_dim = 0;
  bool have_vertices = false;
  std::int64_t nv = 0;
  auto read_items = [&](int width, std::vector<int>* items, std::vector<int>* markers, const char* what) {
    const std::int64_t n = in.integer_in("item count", 0, INT32_MAX);
    if (!have_vertices) in.fail(ErrorCode::Syntax, std::string(what) + " before Vertices");
    for (std::int64_t i = 0; i < n; ++i) {
      for (int k = 0; k < width; ++k) {
        const std::int64_t v = in.integer("vertex number");
        if (v < 1 || v > nv)
          in.fail(ErrorCode::IndexOutOfRange,
                  std::string(what) + " " + std::to_string(i + 1) + " refers to vertex " + std::to_string(v) +
                      " of " + std::to_string(nv),
                  v);
        if (items) items->push_back(static_cast<int>(v - 1));
      }
      const std::int64_t ref = in.integer_in("reference", INT32_MIN, INT32_MAX);
      if (markers) markers->push_back(static_cast<int>(ref));
    }
  };
  if (in.at_end()) in.fail(ErrorCode::Truncated, "empty file");
  while (!in.at_end()) {
    const std::string keyword(in.token("keyword"));
    if (keyword == "MeshVersionFormatted") {
      in.integer_in("mesh version", 1, 4);
    } else if (keyword == "Dimension") {
      file_dim = static_cast<int>(in.integer_in("dimension", 2, 3));
      if (file_dim < dim) in.fail(ErrorCode::Unsupported, "a 2D Medit file holds no tetrahedral mesh");
    } else if (keyword == "Vertices") {
      if (file_dim == 0) in.fail(ErrorCode::Syntax, "Vertices before Dimension");
      if (have_vertices) in.fail(ErrorCode::Syntax, "second Vertices section");
      have_vertices = true;
      nv = in.integer_in("vertex count", 0, INT32_MAX - 1);
      raw.xyz.reserve(static_cast<std::size_t>(std::min(3 * nv, max_numbers)));
      raw.vertex_markers.reserve(static_cast<std::size_t>(std::min(nv, max_numbers)));
      for (std::int64_t i = 0; i < nv; ++i) {
        for (int k = 0; k < file_dim; ++k) raw.xyz.push_back(in.real("vertex coordinate"));
        if (file_dim == 2) raw.xyz.push_back(0.0);
        raw.vertex_markers.push_back(static_cast<int>(in.integer_in("vertex reference", INT32_MIN, INT32_MAX)));
      }
    } else if (keyword == "Triangles") {
      if (dim == 2)
        read_items(3, &raw.cells, &raw.cell_markers, "triangle");
      else
        read_items(3, &raw.faces, &raw.face_markers, "triangle");
    } else if (keyword == "Tetrahedra") {
      if (dim == 2) in.fail(ErrorCode::Unsupported, "tetrahedra in a triangle mesh");
      read_items(4, &raw.cells, &raw.cell_markers, "tetrahedron");
    } else if (keyword == "Edges") {
      if (dim == 2)
        read_items(2, &raw.faces, &raw.face_markers, "edge");
      else
        read_items(2, nullptr, nullptr, "edge");
    } else if (keyword == "Corners" || keyword == "RequiredVertices" || keyword == "Ridges" ||
               keyword == "RequiredEdges" || keyword == "RequiredTriangles" || keyword == "RequiredTetrahedra") {
      const std::int64_t n = in.integer_in("item count", 0, INT32_MAX);
      for (std::int64_t i = 0; i < n; ++i) in.integer("item number");
    } else if (keyword == "End") {
      break;
    } else {
      in.fail(ErrorCode::Unsupported, "Medit keyword '" + keyword + "'");
    }
  }
  if (!have_vertices) in.fail(ErrorCode::Truncated, "no Vertices section");
  return raw;
}

}  // namespace pqmesh::detail
