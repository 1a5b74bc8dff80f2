#pragma once
// The output options of the commands that write meshes: --format (the names
// of to_string(MeshFormat) plus the usual extensions) and --compress.
#include <optional>

#include "args.hpp"
#include "pqmesh/mesh_io.hpp"

namespace pqmesh::cli {

// Absent: nullopt (the output's extension decides). svg only when
// allow_svg (2D meshes); anything else throws UsageError naming the choices.
// "msh41b" (or "msh4b") is binary Gmsh 4.1.
std::optional<MeshFormat> format_option(const Args& args, bool allow_svg);

// --compress (a flag the command must accept), for WriteOptions::compress:
// false when absent; true when given for binary Vtu output; UsageError for
// any other format (checked before any work, so call it early).
bool compress_option(const Args& args, MeshFormat format, bool binary = true);

}  // namespace pqmesh::cli
