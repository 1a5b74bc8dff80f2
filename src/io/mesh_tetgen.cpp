// Triangle (2D) and TetGen (3D) mesh files, 1-based:
//   .node  "<n> <dim> 0 <0|1>" then "<i> <x> <y> [<z>] [<vertex marker>]"
//   .ele   "<n> <3|4> <0|1>"   then "<i> <a> <b> <c> [<d>] [<marker>]"
//          (the region marker is the element attribute, written as an integer)
//   .poly  (2D) "0 2 0 <0|1>" (nodes are in .node), then the segments
//          "<n> <0|1>", "<i> <a> <b> [<marker>]", then "0" holes
//   .face  (3D) "<n> <0|1>", "<i> <a> <b> <c> [<marker>]"
// The marker column is present exactly when the mesh has that marker array.
//
// Orientation. Triangle lists triangle corners counter-clockwise, as pqmesh.
// TetGen's .ele orientation depends on the version: TetGen 1.5/1.6 write the
// four stored vertices in order and their checkmesh() reports a tetrahedron as
// inverted unless Shewchuk's orient3d of the stored order (v3, v2, v1, v0) is
// negative, i.e. unless det(v1-v0, v2-v0, v3-v0) > 0: pqmesh's (and VTK's)
// positive orientation, which the writer uses; older development versions
// swapped the first two vertices on output ("so that Orient3D() > 0", the
// opposite). We follow 1.5/1.6, the version Debian ships; the reader keeps the
// file's order (an inverted tetrahedron is for the checker to report). TetGen's .face lists boundary triangles so that the
// right-hand normal points INTO the volume (comment of outsubfaces() in
// tetgen.cxx), the opposite of pqmesh: the writer writes (a, c, b) and the
// reader reverses back.
#include <algorithm>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "io/mesh_common.hpp"
#include "io/mesh_input.hpp"
#include "io/mesh_output.hpp"

namespace pqmesh::detail {

namespace {

bool file_exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

}  // namespace

template <class M>
void write_tetgen(const M& mesh, const std::string& path) {
  using T = MeshTraits<M>;
  constexpr int D = T::dim;
  const std::string stem = tetgen_stem(path);
  AtomicFile node_file(stem + ".node");
  AtomicFile ele_file(stem + ".ele");
  AtomicFile face_file(stem + (D == 2 ? ".poly" : ".face"));
  {
    BufferedWriter out(node_file.file(), node_file.path());
    const bool marked = !mesh.vertex_markers.empty();
    out.put_int(static_cast<std::int64_t>(mesh.vertices.size())).put(' ').put_int(D).put(" 0 ");
    out.put_int(marked ? 1 : 0).put('\n');
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      out.put_int(static_cast<std::int64_t>(i + 1));
      for (int k = 0; k < D; ++k) out.put(' ').put_double(coord(mesh.vertices[i], k));
      if (marked) out.put(' ').put_int(mesh.vertex_markers[i]);
      out.put('\n');
    }
    out.flush();
  }
  {
    BufferedWriter out(ele_file.file(), ele_file.path());
    const auto& cells = T::cells(mesh);
    const auto& markers = T::cell_markers(mesh);
    out.put_int(static_cast<std::int64_t>(cells.size())).put(' ').put_int(D + 1).put(' ');
    out.put_int(markers.empty() ? 0 : 1).put('\n');
    for (std::size_t c = 0; c < cells.size(); ++c) {
      out.put_int(static_cast<std::int64_t>(c + 1));
      for (int v : cells[c]) out.put(' ').put_int(v + 1);
      if (!markers.empty()) out.put(' ').put_int(markers[c]);
      out.put('\n');
    }
    out.flush();
  }
  {
    BufferedWriter out(face_file.file(), face_file.path());
    const auto& faces = T::faces(mesh);
    const auto& markers = T::face_markers(mesh);
    if (D == 2) out.put("0 2 0 ").put_int(mesh.vertex_markers.empty() ? 0 : 1).put('\n');
    out.put_int(static_cast<std::int64_t>(faces.size())).put(' ').put_int(markers.empty() ? 0 : 1).put('\n');
    for (std::size_t f = 0; f < faces.size(); ++f) {
      out.put_int(static_cast<std::int64_t>(f + 1));
      if constexpr (D == 2) {
        out.put(' ').put_int(faces[f][0] + 1).put(' ').put_int(faces[f][1] + 1);
      } else {  // inward normal for TetGen
        out.put(' ').put_int(faces[f][0] + 1).put(' ').put_int(faces[f][2] + 1).put(' ').put_int(faces[f][1] + 1);
      }
      if (!markers.empty()) out.put(' ').put_int(markers[f]);
      out.put('\n');
    }
    if (D == 2) out.put("0\n");
    out.flush();
  }
  // All three files are complete before the first rename.
  node_file.finish();
  ele_file.finish();
  face_file.finish();
  node_file.commit();
  ele_file.commit();
  face_file.commit();
}

template void write_tetgen(const TriMesh2&, const std::string&);
template void write_tetgen(const TetMesh3&, const std::string&);

namespace {

int read_marker(TextReader& in, const char* what) {
  const double v = in.real(what);
  if (v != static_cast<double>(static_cast<long long>(v)) || v < INT32_MIN || v > INT32_MAX)
    in.fail(ErrorCode::Syntax, std::string(what) + " is not an integer");
  return static_cast<int>(v);
}

// Reads "<count> items" of `width` vertex numbers, relative to base.
void read_connectivity(TextReader& in, std::int64_t n, int width, int used, std::int64_t base, std::int64_t nv,
                       int nattr, std::vector<int>& items, std::vector<int>* markers, bool reverse3,
                       const char* what) {
  for (std::int64_t i = 0; i < n; ++i) {
    in.integer("item number");
    int v[16];
    for (int k = 0; k < width; ++k) {
      const std::int64_t x = in.integer("vertex number");
      if (x < base || x >= base + nv)
        in.fail(ErrorCode::IndexOutOfRange,
                std::string(what) + " " + std::to_string(i + base) + " refers to vertex " + std::to_string(x) +
                    " (vertices are " + std::to_string(base) + ".." + std::to_string(base + nv - 1) + ")",
                x);
      v[k] = static_cast<int>(x - base);
    }
    if (reverse3) std::swap(v[1], v[2]);
    for (int k = 0; k < used; ++k) items.push_back(v[k]);
    for (int a = 0; a < nattr; ++a) {
      const int m = read_marker(in, "marker");
      if (a == 0 && markers) markers->push_back(m);
    }
  }
}

}  // namespace

RawMesh read_tetgen(const std::string& path, int dim) {
  const std::string stem = tetgen_stem(path);
  RawMesh raw;
  std::int64_t base = 1, nv = 0;
  {
    std::string text = read_whole_file(stem + ".node");
    // Every number takes at least two bytes: reserve only what the file can
    // hold, so an absurd vertex count fails as Truncated without allocating.
    const std::int64_t max_numbers = static_cast<std::int64_t>(text.size() / 2 + 1);
    TextReader in(stem + ".node", std::move(text), '#');
    nv = in.integer_in("vertex count", 0, INT32_MAX - 1);
    in.integer_in("dimension", dim, dim);
    const std::int64_t nattr = in.integer_in("attribute count", 0, 1000);
    const std::int64_t nmark = in.integer_in("boundary marker flag", 0, 1);
    raw.xyz.reserve(static_cast<std::size_t>(std::min(3 * nv, max_numbers)));
    for (std::int64_t i = 0; i < nv; ++i) {
      const std::int64_t index = in.integer("vertex number");
      if (i == 0) {
        if (index != 0 && index != 1) in.fail(ErrorCode::WrongCount, "first vertex number must be 0 or 1", index);
        base = index;
      } else if (index != base + i) {
        in.fail(ErrorCode::WrongCount, "vertex number " + std::to_string(index) + ", expected " +
                                           std::to_string(base + i), index);
      }
      for (int k = 0; k < dim; ++k) raw.xyz.push_back(in.real("vertex coordinate"));
      if (dim == 2) raw.xyz.push_back(0.0);
      for (std::int64_t a = 0; a < nattr; ++a) in.real("vertex attribute");
      if (nmark) raw.vertex_markers.push_back(read_marker(in, "vertex marker"));
    }
  }
  {
    TextReader in(stem + ".ele", read_whole_file(stem + ".ele"), '#');
    const std::int64_t n = in.integer_in("element count", 0, INT32_MAX);
    const int width = static_cast<int>(dim == 2 ? in.integer_in("nodes per triangle", 3, 6)
                                                 : in.integer_in("nodes per tetrahedron", 4, 10));
    if (width != dim + 1 && width != (dim == 2 ? 6 : 10))
      in.fail(ErrorCode::Unsupported, "elements with " + std::to_string(width) + " nodes");
    const int nattr = static_cast<int>(in.integer_in("attribute count", 0, 1000));
    // Higher-order elements list the corners first; only they are kept.
    read_connectivity(in, n, width, dim + 1, base, nv, nattr, raw.cells, &raw.cell_markers, false, "element");
  }
  const std::string boundary = stem + (dim == 2 ? ".poly" : ".face");
  if (file_exists(boundary)) {
    TextReader in(boundary, read_whole_file(boundary), '#');
    if (dim == 2) {
      const std::int64_t pn = in.integer_in("vertex count", 0, INT32_MAX - 1);
      in.integer_in("dimension", 2, 2);
      const std::int64_t nattr = in.integer_in("attribute count", 0, 1000);
      const std::int64_t nmark = in.integer_in("boundary marker flag", 0, 1);
      if (pn != 0 && pn != nv)
        in.fail(ErrorCode::WrongCount, ".poly lists " + std::to_string(pn) + " vertices, .node has " +
                                           std::to_string(nv));
      for (std::int64_t i = 0; i < pn * (3 + nattr + nmark); ++i) in.token("vertex data");
    }
    const std::int64_t n = in.integer_in(dim == 2 ? "segment count" : "face count", 0, INT32_MAX);
    const int marked = static_cast<int>(in.integer_in("boundary marker flag", 0, 1));
    read_connectivity(in, n, dim, dim, base, nv, marked, raw.faces, &raw.face_markers, dim == 3,
                      dim == 2 ? "segment" : "face");
  }
  return raw;
}

}  // namespace pqmesh::detail
