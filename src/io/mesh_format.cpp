// Format selection and the public entry points of pqmesh/mesh_io.hpp.
#include <string>

#include "io/mesh_common.hpp"
#include "pqmesh/errors.hpp"
#include "pqmesh/mesh_io.hpp"

namespace pqmesh {

const char* to_string(MeshFormat format) {
  switch (format) {
    case MeshFormat::Vtu: return "vtu";
    case MeshFormat::Msh41: return "msh41";
    case MeshFormat::Msh41Binary: return "msh41b";
    case MeshFormat::Msh22: return "msh22";
    case MeshFormat::Medit: return "medit";
    case MeshFormat::TetgenNodeEle: return "tetgen";
    case MeshFormat::Svg: return "svg";
  }
  return "unknown";
}

namespace {

bool ends_with(const std::string& s, const char* suffix) {
  const std::string e(suffix);
  return s.size() > e.size() && s.compare(s.size() - e.size(), e.size(), e) == 0;
}

template <class M>
void write_any(const M& mesh, const std::string& path, const WriteOptions& options) {
  const MeshFormat format = options.format ? *options.format : mesh_format_from_path(path);
  detail::check_for_write(mesh, options);
  switch (format) {
    case MeshFormat::Vtu: detail::write_vtu(mesh, path, options); return;
    case MeshFormat::Msh41: detail::write_gmsh(mesh, path, detail::GmshLayout::Ascii41); return;
    case MeshFormat::Msh41Binary: detail::write_gmsh(mesh, path, detail::GmshLayout::Binary41); return;
    case MeshFormat::Msh22: detail::write_gmsh(mesh, path, detail::GmshLayout::Ascii22); return;
    case MeshFormat::Medit: detail::write_medit(mesh, path); return;
    case MeshFormat::TetgenNodeEle: detail::write_tetgen(mesh, path); return;
    case MeshFormat::Svg:
      if constexpr (detail::MeshTraits<M>::dim == 2) {
        detail::write_svg(mesh, path, options);
        return;
      } else {
        throw ParseError(ErrorCode::Unsupported, "SVG output is for 2D meshes only", {}, path, 0);
      }
  }
}

detail::RawMesh read_any(const std::string& path, int dim) {
  switch (mesh_format_from_path(path)) {
    case MeshFormat::Vtu: return detail::read_vtu(path, dim);
    case MeshFormat::Msh41:
    case MeshFormat::Msh41Binary:
    case MeshFormat::Msh22: return detail::read_gmsh(path, dim);
    case MeshFormat::Medit: return detail::read_medit(path, dim);
    case MeshFormat::TetgenNodeEle: return detail::read_tetgen(path, dim);
    case MeshFormat::Svg: break;
  }
  throw ParseError(ErrorCode::Unsupported, "SVG files cannot be read as meshes", {}, path, 0);
}

}  // namespace

MeshFormat mesh_format_from_path(const std::string& path, bool msh22) {
  if (ends_with(path, ".vtu")) return MeshFormat::Vtu;
  if (ends_with(path, ".msh")) return msh22 ? MeshFormat::Msh22 : MeshFormat::Msh41;
  if (ends_with(path, ".mesh")) return MeshFormat::Medit;
  if (ends_with(path, ".node") || ends_with(path, ".ele") || ends_with(path, ".face") || ends_with(path, ".poly"))
    return MeshFormat::TetgenNodeEle;
  if (ends_with(path, ".svg")) return MeshFormat::Svg;
  throw ParseError(ErrorCode::Unsupported,
                   "unknown mesh file extension (expected .vtu, .msh, .mesh, .node/.ele, .svg)", {}, path, 0);
}

void write_mesh(const TriMesh2& mesh, const std::string& path, const WriteOptions& options) {
  write_any(mesh, path, options);
}

void write_mesh(const TetMesh3& mesh, const std::string& path, const WriteOptions& options) {
  write_any(mesh, path, options);
}

TriMesh2 read_trimesh(const std::string& path) { return detail::to_trimesh(read_any(path, 2), path); }

TetMesh3 read_tetmesh(const std::string& path) { return detail::to_tetmesh(read_any(path, 3), path); }

}  // namespace pqmesh
