#include "format_option.hpp"

#include <string>

namespace pqmesh::cli {

std::optional<MeshFormat> format_option(const Args& args, bool allow_svg) {
  const auto text = args.option("--format");
  if (!text) return std::nullopt;
  if (*text == "vtu") return MeshFormat::Vtu;
  if (*text == "msh" || *text == "msh41") return MeshFormat::Msh41;
  if (*text == "msh41b" || *text == "msh4b") return MeshFormat::Msh41Binary;
  if (*text == "msh22") return MeshFormat::Msh22;
  if (*text == "mesh" || *text == "medit") return MeshFormat::Medit;
  if (*text == "node" || *text == "tetgen") return MeshFormat::TetgenNodeEle;
  if (allow_svg && *text == "svg") return MeshFormat::Svg;
  if (allow_svg) throw UsageError("--format must be vtu, msh, msh41b, msh22, mesh, node or svg, got '" + *text + "'");
  throw UsageError("--format must be vtu, msh, msh41b, msh22, mesh or node for a 3D mesh, got '" + *text + "'");
}

bool compress_option(const Args& args, MeshFormat format, bool binary) {
  if (!args.flag("--compress")) return false;
  if (format != MeshFormat::Vtu || !binary)
    throw UsageError(std::string("--compress applies to binary .vtu output only, not ") + to_string(format) +
                     (binary ? "" : " (--ascii)"));
  return true;
}

}  // namespace pqmesh::cli
