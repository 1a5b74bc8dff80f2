// Entry points of pqmesh/read_domain.hpp: dispatch on the file extension.
#include "pqmesh/read_domain.hpp"

#include "io/read_formats.hpp"
#include "io/read_text_tokens.hpp"

namespace pqmesh {

namespace {

[[noreturn]] void unsupported_extension(const std::string& path, const std::string& wanted) {
  throw ParseError(ErrorCode::Unsupported,
                   "unknown input extension '" + detail::lower_extension(path) + "' (expected " + wanted + ")", {}, path,
                   0);
}

}  // namespace

int domain_dimension(const std::string& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".poly") return detail::poly_dimension(path);
  if (ext == ".smesh" || ext == ".off" || ext == ".stl" || ext == ".obj" || ext == ".mesh") return 3;
  unsupported_extension(path, ".poly, .smesh, .off, .stl, .obj or .mesh");
}

Pslg2 read_pslg(const std::string& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext != ".poly") unsupported_extension(path, ".poly");
  const int dim = detail::poly_dimension(path);
  if (dim != 2)
    throw ParseError(ErrorCode::WrongCount, "a 2D domain needs dimension 2, the file has " + std::to_string(dim), {},
                     path, 1);
  return detail::read_triangle_poly(path);
}

Plc3 read_plc(const std::string& path, const ReadOptions& options, ReadReport* report) {
  ReadReport local;
  ReadReport& r = report ? *report : local;
  r = ReadReport{};
  const std::string ext = detail::lower_extension(path);
  if (ext == ".poly") {
    const int dim = detail::poly_dimension(path);
    if (dim != 3)
      throw ParseError(ErrorCode::WrongCount, "a 3D domain needs dimension 3, the file has " + std::to_string(dim), {},
                       path, 1);
    return detail::read_tetgen_poly(path, r);
  }
  if (ext == ".smesh") return detail::read_tetgen_smesh(path, r);
  if (ext == ".off") return detail::read_off(path, options, r);
  if (ext == ".stl") return detail::read_stl(path, options, r);
  if (ext == ".obj") return detail::read_obj(path, options, r);
  if (ext == ".mesh") return detail::read_medit_surface(path, options, r);
  unsupported_extension(path, ".poly, .smesh, .off, .stl, .obj or .mesh");
}

}  // namespace pqmesh
