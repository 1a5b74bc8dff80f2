#pragma once
// Writing and reading output meshes (TriMesh2, TetMesh3) in the formats that
// downstream tools read: VTK XML unstructured grid (.vtu), Gmsh MSH 4.1 and
// 2.2 (.msh), Medit (.mesh), Triangle/TetGen (.node/.ele/.poly or .face), and
// an SVG picture of a 2D mesh (write only). The head comment of each
// src/io/mesh_<format>.cpp gives the exact layout written; the rules that
// matter to callers are here.
//
// Writers
//   - are atomic: everything is written to "<path>.tmp-<pid>" and renamed onto
//     <path> only after the last byte was written and flushed; on any failure
//     the temporary file is removed and pqmesh::Error is thrown, so a failed
//     run never leaves a partial output file (the Triangle/TetGen format writes
//     2 or 3 files: all temporaries are complete before the first rename);
//   - are deterministic: the same mesh and options give byte-identical files;
//     doubles are printed in the shortest form that reads back to the same
//     bits (std::to_chars), so ASCII files round-trip coordinates exactly;
//   - keep pqmesh's orientation (pqmesh/mesh.hpp) where the format agrees with
//     it, and convert where it does not (TetGen .face lists boundary triangles
//     with the normal pointing into the mesh: the writer reverses them).
//
// Markers
//   Element markers (regions), boundary edge/face markers and vertex markers
//   are written where the format can hold them (Vtu: element and vertex
//   markers; Msh: all three, vertex markers as $NodeData "vertex_marker";
//   Medit and TetGen/Triangle: all three). Formats
//   that need a marker on every element (Gmsh, Medit) write 0 for missing
//   markers, and every reader returns an EMPTY marker vector when all markers
//   of a kind are 0, so "no markers" and "all markers 0" are the same thing.
//   Gmsh physical tags must be positive; marker m >= 1 becomes physical tag m,
//   marker m <= 0 becomes tag M + 1 - m, where M is the largest positive
//   marker of that dimension (0 if none). Every physical group is also named
//   "marker <m>" in $PhysicalNames, and the reader takes the marker from that
//   name when present (else marker = physical tag), so markers round-trip.
//
// Readers
//   throw ParseError naming the file and line for anything malformed, and
//   translate each format's own conventions into pqmesh's (TetGen's inward
//   .face normals are reversed). Elements keep the vertex order of the file:
//   a negatively oriented or degenerate element is the validity checker's to
//   report (pqmesh check), so readers never repair orientation.
#include <optional>
#include <string>
#include <vector>

#include "pqmesh/errors.hpp"
#include "pqmesh/mesh.hpp"

namespace pqmesh {

enum class MeshFormat {
  Vtu,            // .vtu  VTK XML UnstructuredGrid (volume/area cells only)
  Msh41,          // .msh  Gmsh 4.1 ASCII
  Msh41Binary,    // .msh  Gmsh 4.1 binary (chosen explicitly; .msh means Msh41)
  Msh22,          // .msh  Gmsh 2.2 ASCII
  Medit,          // .mesh Medit ASCII (MeshVersionFormatted 2)
  TetgenNodeEle,  // .node + .ele + (.face in 3D | .poly in 2D), 1-based
  Svg,            // .svg  picture of a 2D mesh (write only)
};

// Stable lower-case name: "vtu", "msh41", "msh41b", "msh22", "medit",
// "tetgen", "svg".
const char* to_string(MeshFormat format);

// The format a file name asks for, by extension (case-sensitive): .vtu, .msh
// (Msh41, or Msh22 when msh22 is true), .mesh, .node/.ele/.face/.poly, .svg.
// Throws ParseError(Unsupported) naming the path for anything else.
MeshFormat mesh_format_from_path(const std::string& path, bool msh22 = false);

// Extra per-element data written next to the mesh, e.g. a quality measure
// computed by the caller. values has one entry per triangle (2D) or
// tetrahedron (3D). Written by Vtu (CellData) only; other formats ignore it
// (a Gmsh $ElementData over the elements but not the boundary items is
// rejected by meshio, so Msh files do not carry fields).
struct CellField {
  std::string name;  // non-empty, unique, not "marker"; no '"', '<', '>', '&'
  std::vector<double> values;
  // Vtu: store the values as Float32 (half the bytes) instead of Float64. For
  // display values such as quality measures: each value is rounded to the
  // nearest float (about 7 significant digits); a value beyond the float
  // range, an infinity included, is written as +-FLT_MAX (readers reject
  // non-finite values).
  bool single_precision = false;
};

struct WriteOptions {
  // Empty: taken from the path by mesh_format_from_path(path).
  std::optional<MeshFormat> format;
  // Vtu only: true writes raw appended binary data (fast path), false ASCII.
  // Msh: the format decides (Msh41Binary is binary, Msh41/Msh22 ASCII).
  bool binary = true;
  // Vtu with binary only: compress every appended array with zlib
  // (compressor="vtkZLibDataCompressor"); smaller files, slower writing.
  bool compress = false;
  std::vector<CellField> cell_fields;
  // Svg only: width of the picture in pixels (height follows the aspect ratio).
  double svg_width = 800;
};

// Write a mesh. For TetgenNodeEle, path names any of the files (or the common
// stem); "<stem>.node", "<stem>.ele" and "<stem>.poly" (2D) / "<stem>.face"
// (3D) are written. Throws pqmesh::Error on I/O failure, InvalidInput when a
// marker or cell-field array does not match the mesh (the file is not
// touched), ParseError(Unsupported) for Svg with a 3D mesh.
void write_mesh(const TriMesh2& mesh, const std::string& path, const WriteOptions& options = {});
void write_mesh(const TetMesh3& mesh, const std::string& path, const WriteOptions& options = {});

// Read a mesh; the format comes from the extension (.msh: the version is read
// from the file). Vtu: ASCII, inline base64 and appended raw/base64 data,
// uncompressed or compressed with zlib, LZ4 or LZMA, UInt32 or UInt64
// headers. Msh: 4.1 and 2.2 ASCII (binary .msh is written, not read).
// Medit: ASCII. TetGen/Triangle: 0- or 1-based numbering. A 2D mesh must lie
// in the plane z = 0 where the format stores z (Vtu, Msh).
TriMesh2 read_trimesh(const std::string& path);
TetMesh3 read_tetmesh(const std::string& path);

}  // namespace pqmesh
