#include "load.hpp"

#include "pqmesh/errors.hpp"
#include "pqmesh/mesh_io.hpp"

namespace pqmesh::cli {

ReadOptions read_options_from(const Args& args) {
  ReadOptions options;
  options.merge_coplanar = !args.flag("--no-merge");
  options.merge_angle_degrees = args.number("--merge-angle", 0);
  if (options.merge_angle_degrees < 0 || options.merge_angle_degrees >= 90)
    throw UsageError("--merge-angle must be in [0, 90) degrees");
  return options;
}

LoadedDomain load_domain(const std::string& path, const ReadOptions& options) {
  LoadedDomain loaded;
  if (domain_dimension(path) == 2) {
    loaded.domain = make_domain(read_pslg(path));
  } else {
    loaded.domain = make_domain(read_plc(path, options, &loaded.report));
  }
  return loaded;
}

int dimension_option(const Args& args) {
  const auto text = args.option("--dim");
  if (!text) return 0;
  if (*text == "2") return 2;
  if (*text == "3") return 3;
  throw UsageError("--dim must be 2 or 3");
}

AnyMesh load_mesh(const std::string& path, int dimension) {
  if (dimension == 2) return read_trimesh(path);
  if (dimension == 3) return read_tetmesh(path);
  // Auto-detect: a file with tetrahedra is a 3D mesh. A 2D file may not parse
  // as a tetrahedral one (the readers are strict), so fall back on ParseError.
  try {
    TetMesh3 mesh = read_tetmesh(path);
    if (!mesh.tetrahedra.empty()) return mesh;
  } catch (const ParseError& e) {
    if (e.code() == ErrorCode::Unreadable) throw;
  }
  return read_trimesh(path);
}

}  // namespace pqmesh::cli
