#pragma once
// Pieces shared by the mesh format files (mesh_*.cpp): uniform access to
// TriMesh2/TetMesh3 for the writers, checks before writing, the generic
// result of a reader and its conversion to a mesh, and the Gmsh marker to
// physical-tag rule. Format entry points are declared at the bottom.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "pqmesh/mesh.hpp"
#include "pqmesh/mesh_io.hpp"

namespace pqmesh::detail {

template <class M>
struct MeshTraits;

template <>
struct MeshTraits<TriMesh2> {
  static constexpr int dim = 2;
  static constexpr int cell_nodes = 3;
  static constexpr int face_nodes = 2;
  static const auto& cells(const TriMesh2& m) { return m.triangles; }
  static const auto& cell_markers(const TriMesh2& m) { return m.triangle_markers; }
  static const auto& faces(const TriMesh2& m) { return m.edges; }
  static const auto& face_markers(const TriMesh2& m) { return m.edge_markers; }
};

template <>
struct MeshTraits<TetMesh3> {
  static constexpr int dim = 3;
  static constexpr int cell_nodes = 4;
  static constexpr int face_nodes = 3;
  static const auto& cells(const TetMesh3& m) { return m.tetrahedra; }
  static const auto& cell_markers(const TetMesh3& m) { return m.tetrahedron_markers; }
  static const auto& faces(const TetMesh3& m) { return m.faces; }
  static const auto& face_markers(const TetMesh3& m) { return m.face_markers; }
};

inline double coord(const Vec2& p, int k) { return k == 0 ? p.x : (k == 1 ? p.y : 0.0); }
inline double coord(const Vec3& p, int k) { return axis_coord(p, k); }

// Marker of item i, 0 when the marker array is empty.
inline int marker_or_zero(const std::vector<int>& markers, std::size_t i) {
  return markers.empty() ? 0 : markers[i];
}

// Throws InvalidInput when marker arrays have the wrong length, an element
// refers to a missing vertex, a coordinate is not finite, or a cell field is
// malformed (checked before any file is created).
void check_for_write(const TriMesh2& mesh, const WriteOptions& options);
void check_for_write(const TetMesh3& mesh, const WriteOptions& options);

// What a reader produces before it becomes a TriMesh2/TetMesh3: coordinates
// always with three components, connectivity 0-based and already checked
// against the vertex count.
struct RawMesh {
  std::vector<double> xyz;  // 3 per vertex
  std::vector<int> vertex_markers;
  std::vector<int> cells;  // cell_nodes per cell
  std::vector<int> cell_markers;
  std::vector<int> faces;  // face_nodes per face
  std::vector<int> face_markers;
};

// Orients elements (module doc of pqmesh/mesh_io.hpp), empties all-zero
// marker arrays, and for 2D checks z == 0 (ParseError Unsupported naming the
// first vertex that is off the plane).
TriMesh2 to_trimesh(RawMesh&& raw, const std::string& path);
TetMesh3 to_tetmesh(RawMesh&& raw, const std::string& path);

// Gmsh physical tags for the markers of one dimension: distinct markers in
// increasing order, each with its entity tag (1, 2, ...) and its physical tag
// (marker m >= 1 -> m; m <= 0 -> M + 1 - m, M = largest positive marker or 0).
struct PhysicalGroups {
  std::vector<int> markers;
  std::vector<int> physical_tags;
  // Entity tag (1-based index into markers) of marker m, which must be present.
  int entity_of(int marker) const;
};
// markers empty means every one of `count` items has marker 0.
PhysicalGroups make_physical_groups(const std::vector<int>& markers, std::size_t count);

// Format entry points (one file each).
template <class M>
void write_vtu(const M& mesh, const std::string& path, const WriteOptions& options);
enum class GmshLayout { Ascii41, Ascii22, Binary41 };
template <class M>
void write_gmsh(const M& mesh, const std::string& path, GmshLayout layout);
template <class M>
void write_medit(const M& mesh, const std::string& path);
template <class M>
void write_tetgen(const M& mesh, const std::string& path);
void write_svg(const TriMesh2& mesh, const std::string& path, const WriteOptions& options);

// Readers: dim is 2 (triangles + edges) or 3 (tetrahedra + faces).
RawMesh read_vtu(const std::string& path, int dim);
RawMesh read_gmsh(const std::string& path, int dim);
RawMesh read_medit(const std::string& path, int dim);
RawMesh read_tetgen(const std::string& path, int dim);

// "<stem>" of a Triangle/TetGen path: the path without a trailing .node,
// .ele, .face or .poly.
std::string tetgen_stem(const std::string& path);

}  // namespace pqmesh::detail
