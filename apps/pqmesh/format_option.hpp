#pragma once
// The --format option of `pqmesh mesh`: the names of to_string(MeshFormat)
// plus the usual extensions.
#include <optional>

#include "args.hpp"
#include "pqmesh/mesh_io.hpp"

namespace pqmesh::cli {

// Absent: nullopt (the output's extension decides). svg only when
// allow_svg (2D meshes); anything else throws UsageError naming the choices.
std::optional<MeshFormat> format_option(const Args& args, bool allow_svg);

}  // namespace pqmesh::cli
