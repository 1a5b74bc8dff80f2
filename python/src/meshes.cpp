// TriMesh / TetMesh: the library's TriMesh2 / TetMesh3 with read-only numpy
// views of their arrays (the mesh object owns the memory). Meshes made by
// triangulate / tetrahedralize also carry the summary figures as attributes
// (mesh2d.cpp, mesh3d.cpp); a mesh can also be built from arrays, e.g. to run
// the checker on a mesh made elsewhere.
#include <memory>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "pqmesh/mesh.hpp"
#include "pqmesh/mesh_io.hpp"

namespace pqmesh::python {
namespace {

std::shared_ptr<TriMesh2> trimesh(py::handle points, py::handle triangles, py::handle edges, py::handle edge_markers,
                                  py::handle triangle_markers, py::handle vertex_markers) {
  auto mesh = std::make_shared<TriMesh2>();
  mesh->vertices = to_points2(points, "points");
  mesh->triangles = to_index_rows<3>(triangles, "triangles");
  if (!edges.is_none()) mesh->edges = to_index_rows<2>(edges, "edges");
  if (!edge_markers.is_none()) mesh->edge_markers = to_ints(edge_markers, "edge_markers");
  if (!triangle_markers.is_none()) mesh->triangle_markers = to_ints(triangle_markers, "triangle_markers");
  if (!vertex_markers.is_none()) mesh->vertex_markers = to_ints(vertex_markers, "vertex_markers");
  return mesh;
}

std::shared_ptr<TetMesh3> tetmesh(py::handle points, py::handle tetrahedra, py::handle faces, py::handle face_markers,
                                  py::handle tetrahedron_markers, py::handle vertex_markers) {
  auto mesh = std::make_shared<TetMesh3>();
  mesh->vertices = to_points3(points, "points");
  mesh->tetrahedra = to_index_rows<4>(tetrahedra, "tetrahedra");
  if (!faces.is_none()) mesh->faces = to_index_rows<3>(faces, "faces");
  if (!face_markers.is_none()) mesh->face_markers = to_ints(face_markers, "face_markers");
  if (!tetrahedron_markers.is_none()) mesh->tetrahedron_markers = to_ints(tetrahedron_markers, "tetrahedron_markers");
  if (!vertex_markers.is_none()) mesh->vertex_markers = to_ints(vertex_markers, "vertex_markers");
  return mesh;
}

// write_mesh with the format from the path's extension, as `pqmesh mesh -o`.
template <class Mesh>
void write(const Mesh& mesh, const std::string& path) {
  py::gil_scoped_release release;
  write_mesh(mesh, path);
}

constexpr const char* kWriteDoc =
    "Write the mesh; the extension gives the format (.vtu, .msh, .mesh, .node, .svg in 2D), atomically.";

}  // namespace

void bind_meshes(py::module_& m) {
  py::class_<TriMesh2, std::shared_ptr<TriMesh2>>(m, "TriMesh", py::dynamic_attr(), "A triangle mesh (pqmesh::TriMesh2).")
      .def(py::init(&trimesh), py::arg("points"), py::arg("triangles"), py::arg("edges") = py::none(),
           py::arg("edge_markers") = py::none(), py::arg("triangle_markers") = py::none(),
           py::arg("vertex_markers") = py::none())
      .def_property_readonly("dimension", [](const TriMesh2&) { return 2; })
      .def_property_readonly("points", [](py::object self) { return view(self.cast<const TriMesh2&>().vertices, self); })
      .def_property_readonly("triangles", [](py::object self) { return view(self.cast<const TriMesh2&>().triangles, self); },
                             "(M, 3) int32, counter-clockwise.")
      .def_property_readonly("edges", [](py::object self) { return view(self.cast<const TriMesh2&>().edges, self); },
                             "(E, 2) int32: the boundary edges.")
      .def_property_readonly("edge_markers", [](py::object self) { return markers_or_none(self.cast<const TriMesh2&>().edge_markers, self); },
                             "The input segment marker of each boundary edge, or None.")
      .def_property_readonly("triangle_markers", [](py::object self) { return markers_or_none(self.cast<const TriMesh2&>().triangle_markers, self); },
                             "The region attribute of each triangle, or None.")
      .def_property_readonly("vertex_markers", [](py::object self) { return markers_or_none(self.cast<const TriMesh2&>().vertex_markers, self); })
      .def("write", &write<TriMesh2>, py::arg("path"), kWriteDoc)
      .def("__repr__", [](const TriMesh2& mesh) {
        return "TriMesh(" + std::to_string(mesh.triangles.size()) + " triangles, " + std::to_string(mesh.vertices.size()) + " vertices)";
      });

  py::class_<TetMesh3, std::shared_ptr<TetMesh3>>(m, "TetMesh", py::dynamic_attr(), "A tetrahedral mesh (pqmesh::TetMesh3).")
      .def(py::init(&tetmesh), py::arg("points"), py::arg("tetrahedra"), py::arg("faces") = py::none(),
           py::arg("face_markers") = py::none(), py::arg("tetrahedron_markers") = py::none(),
           py::arg("vertex_markers") = py::none())
      .def_property_readonly("dimension", [](const TetMesh3&) { return 3; })
      .def_property_readonly("points", [](py::object self) { return view(self.cast<const TetMesh3&>().vertices, self); })
      .def_property_readonly("tetrahedra", [](py::object self) { return view(self.cast<const TetMesh3&>().tetrahedra, self); },
                             "(M, 4) int32, positive volume.")
      .def_property_readonly("faces", [](py::object self) { return view(self.cast<const TetMesh3&>().faces, self); },
                             "(F, 3) int32: the boundary triangles, normals pointing out.")
      .def_property_readonly("face_markers", [](py::object self) { return markers_or_none(self.cast<const TetMesh3&>().face_markers, self); },
                             "The input facet marker of each boundary triangle, or None.")
      .def_property_readonly("tetrahedron_markers", [](py::object self) { return markers_or_none(self.cast<const TetMesh3&>().tetrahedron_markers, self); },
                             "The region attribute of each tetrahedron, or None.")
      .def_property_readonly("vertex_markers", [](py::object self) { return markers_or_none(self.cast<const TetMesh3&>().vertex_markers, self); })
      .def("write", &write<TetMesh3>, py::arg("path"), kWriteDoc)
      .def("__repr__", [](const TetMesh3& mesh) {
        return "TetMesh(" + std::to_string(mesh.tetrahedra.size()) + " tetrahedra, " + std::to_string(mesh.vertices.size()) + " vertices)";
      });
}

}  // namespace pqmesh::python
